"""The single entry point: `/usr/bin/python3 -m analysis COMMAND [options]` from the repository root.

A command is one module's main(argv, prog), which keeps its own options; unknown commands exit 2.
"""
import sys

from .findings import compare
from .charts import convergence_experiment, filter_profiles, pointsets
from .charts import cli as charts_cli
from .report import cli as report_cli
from .teaching import cli as teaching_cli
from .viewer import cli as viewer_cli

COMMANDS = {"report": report_cli.main, "charts": charts_cli.main, "compare": compare.main,
            "convergence": convergence_experiment.main, "pointsets": pointsets.main,
            "filters": filter_profiles.main, "viewer": viewer_cli.main, "teaching": teaching_cli.main}
USAGE = """usage: {prog} COMMAND [options]      (COMMAND -h lists its options)

  report       the HTML report of a study, findings first
  charts       every chart and table of a study CSV
  compare      two study CSVs, before and after a change (exit 1 on an accuracy regression)
  convergence  RMSE against N from the `convergence` experiment's CSV
  pointsets    the spectra and discrepancy charts of the `pointsets` experiment
  filters      filter profiles and frequency responses from `filterprofile`
  viewer       render and export the comparison viewer's images of a study (then `report` shows it)
  teaching     the teaching strand of a study's page, from the viewer's renders (after `viewer`)
"""


def main(argv=None, prog="python3 -m analysis"):
    argv = sys.argv[1:] if argv is None else list(argv)
    if not argv or argv[0] in ("-h", "--help"):
        print(USAGE.format(prog=prog), end="", file=sys.stdout if argv else sys.stderr)
        return 0 if argv else 2
    command = COMMANDS.get(argv[0])
    if command is None:
        print(f"error: unknown command '{argv[0]}' (one of {', '.join(COMMANDS)})", file=sys.stderr)
        return 2
    return command(argv[1:], prog=f"{prog} {argv[0]}")
