"""aliaslab's analysis in Python, run from the repository root as `/usr/bin/python3 -m analysis COMMAND`.

The code is the package aliaslab_analysis/ (its __init__ lists the modules); this folder also holds the
tests (tests/, run as `python3 -m unittest analysis.tests.test_report` from the repository root).
"""
