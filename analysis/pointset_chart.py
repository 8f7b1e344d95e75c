#!/usr/bin/python3
"""`/usr/bin/python3 -m analysis pointsets` at its old path, which the `pointsets` experiment runs (from any
folder: this script's folder is on the import path, so the package imports without sys.path edits)."""
import sys

from aliaslab_analysis.pointset_chart import main

if __name__ == "__main__":
    sys.exit(main())
