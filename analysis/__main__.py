"""`/usr/bin/python3 -m analysis COMMAND [options]` from the repository root (aliaslab_analysis/cli.py)."""
import sys

from .aliaslab_analysis.cli import main

sys.exit(main())
