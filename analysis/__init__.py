"""aliaslab's analysis in Python, run from the repository root as `/usr/bin/python3 -m analysis COMMAND`.

The code is the package aliaslab_analysis/ (its __init__ lists the modules); this folder also holds the
tests (tests/, run as `python3 -m unittest analysis.tests.test_report` from the repository root) and
two scripts kept at their old paths for the C++ experiments that run them (convergence_chart.py,
pointset_chart.py).
"""
