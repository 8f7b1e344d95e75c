#!/usr/bin/env python3
"""slurm_test: experiments/sweep/slurm_sweep.sh submitted to a real single-node Slurm (tests/programs/slurm/cluster.py).

    slurm_test.py --sweep BUILD/bin/sweep --source SOURCE_DIR [--skip REASON]
Exit 0 passed, 1 failed, 77 skipped (Slurm or munge not installed, not root, or --skip: CTest's SKIP_RETURN_CODE).

One small study (fence at 96x96, 3 samplers x spp 4, 16, 128, box and tent, 4 seeds: 27 rows) is run in one
process and as a 3-task job array, whose merge must equal it in every non-timing column, spectra included:
  1. the array: every task ends well; task 1 is then requeued (scontrol requeue) and runs a second time, which
     resumes all of its rows and writes none; the merge job is held until then, and its result is exact;
  2. the faults: task 1 fails (its shard CSV path is a folder), task 2 is cancelled (scancel) mid-run, after
     its first rows: the merge job is refused, naming shards 1 and 2; once the folder is gone, resubmitting
     TASKS=1,2 runs them, task 2 resumes its rows, and the merge is exact;
  3. the references job fails (its cache path is a file): the array is cancelled, never started
     (--kill-on-invalid-dep), and the merge job is refused, naming every shard.
The whole test runs in its own PID namespace when unshare allows it (the kernel then ends every process it
started, whatever happens to it), and checks that nothing it started is left running.
"""
import argparse
import csv
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import traceback

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cluster import CLIENTS, DAEMONS, Cluster  # noqa: E402

TERMINAL = {"COMPLETED", "FAILED", "CANCELLED", "TIMEOUT", "NODE_FAIL", "OUT_OF_MEMORY", "PREEMPTED", "BOOT_FAIL",
            "DEADLINE"}
TIMING = {"trace_ms", "reconstruct_ms", "cpu_ms", "cpu_ms_se", "threads"}  # columns that may differ between runs
SHARDS = 3
DEADLINE = time.monotonic() + 420  # every wait ends by then, well inside CTest's 600 s, so clean-up runs


def until(seconds):
    return min(time.monotonic() + seconds, DEADLINE)


class Failure(Exception):
    pass


def expect(cond, msg):
    if not cond:
        raise Failure(msg)


def study(src, cache):
    return ["--scenes", f"{src}/scenes/fence.txt", "--size", "96", "96", "--samplers", "uniform,jittered,sobol",
            "--spp", "4,16,128", "--filters", "box,tent", "--radii", "1", "--seeds", "4", "--ref-spp", "256",
            "--threads", "1", "--no-images", "--quiet", "--cache", cache, "--target", "area"]


def csv_differences(a, b):
    """Why sweep CSVs a and b differ (same rows in the same order, equal text in every non-timing column)."""
    def load(p):
        with open(p, newline="") as f:
            rows = list(csv.reader(f))
        return rows[0], rows[1:]
    (ha, ra), (hb, rb) = load(a), load(b)
    if ha != hb:
        return [f"headers differ: {sorted(set(ha) ^ set(hb))}"]
    if len(ra) != len(rb):
        return [f"row counts differ: {len(ra)} vs {len(rb)}"]
    keep = [i for i, h in enumerate(ha) if h not in TIMING]
    return [f"row {n + 2} column {ha[i]}: {x[i]} != {y[i]}" for n, (x, y) in enumerate(zip(ra, rb)) for i in keep
            if x[i] != y[i]]


def text(path):
    with open(path) as f:
        return f.read()


def data_lines(path):
    try:
        return max(0, text(path).count("\n") - 1)
    except OSError:
        return 0


def summaries(log):
    """(rows written, rows resumed) of each sweep run logged in a shard's log."""
    try:
        return [(int(w), int(r)) for w, r in re.findall(r"(\d+) rows written, (\d+) resumed", text(log))]
    except OSError:
        return []


class Study:
    """The study's one-process run and its submissions to the cluster."""

    def __init__(self, c, args, tmp):
        self.c, self.tmp = c, tmp
        self.sweep, self.src = args.sweep, args.source
        self.args = study(args.source, os.path.join(tmp, "cache"))

    def submit(self, out, tasks=None):
        env = dict(self.c.env, SWEEP=self.sweep)
        if tasks:
            env["TASKS"] = tasks
        r = self.c.run(["bash", f"{self.src}/experiments/sweep/slurm_sweep.sh", str(SHARDS)] + self.args +
                       ["--out", out], env=env, cwd=self.tmp)
        m = re.search(r"references (\d+), shards (\d+) \(.*\), merge (\d+)", r.stdout)
        expect(m, f"slurm_sweep.sh printed no job ids: {r.stdout}{r.stderr}")
        return m.groups()

    def states(self, job):
        """{array task index (None for a plain job): state} from squeue, finished jobs included."""
        out = self.c.run(["squeue", "-h", "-r", "-t", "all", "-j", job, "-o", "%i|%T"]).stdout.split()
        return {(int(i.split("_")[1]) if "_" in i else None): s for i, s in (line.split("|") for line in out)}

    def wait_ended(self, job, count=1, timeout=300):
        end = until(timeout)
        while time.monotonic() < end:
            s = self.states(job)
            if len(s) == count and set(s.values()) <= TERMINAL:
                return s
            time.sleep(0.3)
        raise Failure(f"job {job} not ended in time: {self.states(job)}\n{self.c.log_tail()}")

    def one(self):
        """The study run in one process (once, on first use: after the first submission, so that the array's
        references job is the one that renders the references into the empty cache)."""
        one = os.path.join(self.tmp, "one")
        if not os.path.exists(os.path.join(one, "study.csv")):
            subprocess.run([self.sweep] + self.args + ["--out", one], check=True, capture_output=True, timeout=300)
        return one

    def expect_same(self, out):
        one = self.one()
        diff = csv_differences(os.path.join(one, "study.csv"), os.path.join(out, "study.csv"))
        expect(not diff, f"{out}/study.csv differs from the one-process run: {diff[:10]}")
        spectra = sorted(os.listdir(os.path.join(one, "spectra")))
        expect(spectra == ["fence.csv"], f"unexpected spectra files of the one-process run: {spectra}")
        for name in spectra:
            a, b = text(os.path.join(one, "spectra", name)), text(os.path.join(out, "spectra", name))
            expect(a.count("\n") > 10 and a == b, f"{out}/spectra/{name} differs from the one-process run's")


def case_array(s):
    out = os.path.join(s.tmp, "array")
    refs, array, merge = s.submit(out)
    s.c.run(["scontrol", "hold", merge])
    expect(s.wait_ended(refs) == {None: "COMPLETED"}, f"references job {refs}: {s.states(refs)}")
    states = s.wait_ended(array, SHARDS)
    expect(states == {i: "COMPLETED" for i in range(SHARDS)}, f"array {array}: {states}")
    shard1, log1 = os.path.join(out, "study.shard-1-of-3.csv"), os.path.join(out, "slurm", "shard-1.log")
    before, first = text(shard1), summaries(log1)
    expect(len(first) == 1 and first[0][0] == data_lines(shard1) > 0, f"task 1's first run: {first}")
    s.c.run(["scontrol", "requeue", f"{array}_1"])
    # A requeued job waits for its credential to expire (AuthInfo cred_expire, 120 s by default): start it now.
    s.c.run(["scontrol", "update", f"JobId={array}_1", "StartTime=now"])
    end = until(240)
    while len(summaries(log1)) < 2 and time.monotonic() < end:
        time.sleep(0.3)
    states = s.wait_ended(array, SHARDS)
    expect(states == {i: "COMPLETED" for i in range(SHARDS)}, f"array {array} after the requeue: {states}")
    runs = summaries(log1)
    expect(runs == [first[0], (0, first[0][0])], f"task 1 should have run twice, resuming every row: {runs}")
    completions = [line for line in text(s.c.path("jobcomp.txt")).splitlines()
                   if f"ArrayJobId={array} ArrayTaskId=1 " in line and "JobState=COMPLETED" in line]
    expect(len(completions) == 2, f"the job-completion log should show task 1 completed twice: {completions}")
    expect(text(shard1) == before, "the requeued task changed its shard CSV")
    s.c.run(["scontrol", "release", merge])
    expect(s.wait_ended(merge) == {None: "COMPLETED"}, f"merge job {merge}: {s.states(merge)}\n" +
           text(os.path.join(out, "slurm", f"merge-{merge}.log")))
    s.expect_same(out)


def case_faults(s):
    out = os.path.join(s.tmp, "faults")
    os.makedirs(os.path.join(out, "study.shard-1-of-3.csv"))  # task 1 cannot write its CSV: it fails
    refs, array, merge = s.submit(out)
    shard2 = os.path.join(out, "study.shard-2-of-3.csv")
    end = until(180)
    while True:  # cancel task 2 once it has written its first rows
        expect(time.monotonic() < end, f"task 2 never got going: {s.states(array)}")
        st = s.states(array).get(2)
        expect(st not in TERMINAL, f"task 2 ended ({st}) before it could be cancelled mid-run")
        if st == "RUNNING" and data_lines(shard2) > 0:
            s.c.run(["scancel", f"{array}_2"])
            break
        time.sleep(0.05)
    states = s.wait_ended(array, SHARDS)
    expect(states == {0: "COMPLETED", 1: "FAILED", 2: "CANCELLED"}, f"array {array}: {states}")
    expect(s.wait_ended(merge) == {None: "FAILED"}, f"merge job {merge} should have been refused: {s.states(merge)}")
    log = text(os.path.join(out, "slurm", f"merge-{merge}.log"))
    expect("shard(s) 1 2 of 3 did not finish" in log and "TASKS=1,2" in log, f"the merge log names no shards: {log}")
    expect(not os.path.exists(os.path.join(out, "study.csv")), "a refused merge wrote study.csv")
    expect("is a folder" in text(os.path.join(out, "slurm", "shard-1.log")), "task 1's log does not say why")
    partial = data_lines(shard2)
    expect(0 < partial < 9, f"task 2's shard should be partial after the cancel: {partial} rows")
    os.rmdir(os.path.join(out, "study.shard-1-of-3.csv"))
    refs, array, merge = s.submit(out, tasks="1,2")
    states = s.wait_ended(array, 2)
    expect(states == {1: "COMPLETED", 2: "COMPLETED"}, f"resubmitted array {array}: {states}")
    runs = summaries(os.path.join(out, "slurm", "shard-2.log"))
    expect(len(runs) == 1 and runs[0][1] > 0 and sum(runs[0]) == 9,
           f"task 2 should have resumed its partial shard ({partial} rows at the cancel): runs {runs}")
    expect(s.wait_ended(merge) == {None: "COMPLETED"}, f"merge job {merge}: {s.states(merge)}\n" +
           text(os.path.join(out, "slurm", f"merge-{merge}.log")))
    s.expect_same(out)
    return f" (task 2 cancelled at {partial} of 9 rows; its rerun resumed {runs[0][1]}, wrote {runs[0][0]})"


def case_refs_fail(s):
    out = os.path.join(s.tmp, "refs_fail")
    os.makedirs(out)
    cache = os.path.join(out, "cache")
    open(cache, "w").close()  # a file where the cache folder should be: the references job fails
    args = s.args
    s.args = args[:args.index("--cache")] + ["--cache", cache]
    try:
        refs, array, merge = s.submit(out)
    finally:
        s.args = args
    expect(s.wait_ended(refs) == {None: "FAILED"}, f"references job {refs}: {s.states(refs)}")
    states = s.wait_ended(array, SHARDS)
    expect(set(states.values()) == {"CANCELLED"}, f"array {array} should be cancelled (dependency never met): {states}")
    expect(s.wait_ended(merge) == {None: "FAILED"}, f"merge job {merge} should have been refused: {s.states(merge)}")
    log = text(os.path.join(out, "slurm", f"merge-{merge}.log"))
    expect("shard(s) 0 1 2 of 3 did not finish" in log, f"the merge log names no shards: {log}")


def in_namespace():
    """Re-runs this test as PID 1 of a new PID namespace when unshare allows it (returns only when it does not)."""
    if os.environ.get("ALIASLAB_SLURM_TEST_NS") == "1" or not shutil.which("unshare"):
        return
    if subprocess.run(["unshare", "--pid", "--fork", "--mount-proc", "true"], capture_output=True).returncode != 0:
        print("slurm_test: no PID namespace here (unshare refused): cleaning up by process tree only")
        return
    sys.stdout.flush()
    os.execvpe("unshare", ["unshare", "--pid", "--fork", "--kill-child=SIGTERM", "--mount-proc", sys.executable,
                           os.path.abspath(__file__)] + sys.argv[1:], dict(os.environ, ALIASLAB_SLURM_TEST_NS="1"))


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--sweep", required=True)
    p.add_argument("--source", required=True)
    p.add_argument("--skip", help="skip, saying why")
    args = p.parse_args()
    if args.skip:
        print(f"slurm_test: skipped: {args.skip}")
        return 77
    os.environ["PATH"] += ":/usr/sbin:/sbin"
    missing = [t for t in DAEMONS + CLIENTS if not shutil.which(t)]
    if missing:
        print(f"slurm_test: skipped: {', '.join(missing)} not installed (Debian packages munge slurmctld slurmd "
              "slurm-client; README command (b) installs them: bash experiments/setup_debian.sh)")
        return 77
    if os.geteuid() != 0:
        print("slurm_test: skipped: needs root (slurmd starts each job as its user)")
        return 77
    in_namespace()
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))
    signal.signal(signal.SIGHUP, lambda *_: sys.exit(129))
    tmp = tempfile.mkdtemp(prefix="aliaslab_slurm_test.")
    t0, ok, c = time.monotonic(), False, Cluster(tmp)
    try:
        with c:
            print(f"slurm_test: cluster up in {time.monotonic() - t0:.1f} s ({tmp})", flush=True)
            s = Study(c, args, tmp)
            for case in (case_array, case_faults, case_refs_fail):
                t = time.monotonic()
                note = case(s)
                print(f"slurm_test: {case.__name__} passed in {time.monotonic() - t:.1f} s{note or ''}", flush=True)
            ok = True
    except Failure as e:
        print(f"slurm_test: FAILED: {e}")
    except Exception:  # the cluster would not start, a Slurm command failed, ...
        print(f"slurm_test: FAILED:\n{traceback.format_exc()}")
    finally:
        left = c.leftovers()
        if left:
            print("slurm_test: FAILED: left running:\n  " + "\n  ".join(left))
            ok = False
    if ok:
        shutil.rmtree(tmp, ignore_errors=True)
    else:
        print(f"slurm_test: kept {tmp} for a look")
    print(f"slurm_test: {'passed' if ok else 'failed'} in {time.monotonic() - t0:.1f} s")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
