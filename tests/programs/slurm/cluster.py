"""A real single-node Slurm for one test, run from a temporary folder and stopped afterwards.

    with Cluster(tmp) as c:      # writes tmp/slurm.conf, starts munged, slurmctld, slurmd; waits for an idle node
        c.run(["sbatch", ...])   # any Slurm client, with SLURM_CONF pointing at the cluster
    # on leaving (also on an exception): jobs cancelled, daemons stopped, every leftover descendant killed

The daemons run in the foreground (munged -F, slurmctld -D, slurmd -D) as children of this process, which makes
itself a child subreaper so that job steps (slurmstepd double-forks) are reparented here and can be found and
killed too. Should the test be killed outright (SIGKILL, CTest's timeout), each daemon dies with it
(PR_SET_PDEATHSIG), and a guard process, detached beforehand, sees its pipe from the test close and kills every
process whose environment holds this cluster's SLURM_CONF (daemons, job steps, jobs: all inherit it). And
slurm_test.py runs the whole test in its own PID namespace when unshare allows it, where the kernel ends
everything once the test ends. Nothing is written outside the folder: munge key, socket, seed, pid files,
logs, Slurm state, spool, and the job-completion log (jobcomp/filetxt: no accounting daemon, so no sacct; the
jobs' states come from squeue, which keeps finished jobs for MinJobAge). Ports are free ones picked at start.
Needs root (slurmd starts jobs as their user) and the Debian packages munge, slurmctld, slurmd, slurm-client.
"""
import ctypes
import os
import pwd
import signal
import socket
import subprocess
import time

DAEMONS = ["munged", "slurmctld", "slurmd"]
CLIENTS = ["sbatch", "squeue", "sinfo", "scontrol", "scancel"]
PR_SET_PDEATHSIG, PR_SET_CHILD_SUBREAPER = 1, 36
_libc = ctypes.CDLL(None, use_errno=True)


def _die_with_parent():
    _libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)


def _free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _descendants(root):
    """Pids of every live process below root (by the parent links in /proc)."""
    parent = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as f:
                    parent[int(entry)] = int(f.read().rsplit(")", 1)[1].split()[1])
            except (OSError, IndexError, ValueError):
                pass
    out, frontier = [], [root]
    while frontier:
        kids = [p for p, pp in parent.items() if pp in frontier]
        out += kids
        frontier = kids
    return out


def _tagged(tag):
    """Pids of live processes (not this one) whose environment holds the entry tag."""
    out = []
    for entry in os.listdir("/proc"):
        if entry.isdigit() and int(entry) != os.getpid():
            try:
                with open(f"/proc/{entry}/environ", "rb") as f:
                    if tag in f.read().split(b"\0"):
                        out.append(int(entry))
            except OSError:
                pass
    return out


def _kill_tagged(tag):
    for _ in range(5):
        pids = _tagged(tag)
        if not pids:
            return
        for pid in pids:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        time.sleep(0.2)


def _start_guard(tag):
    """Detaches a process that, once the returned pipe end is closed (by stop(), or by the kernel when this
    process dies), kills every process tagged with tag, then exits."""
    r, w = os.pipe()
    child = os.fork()
    if child == 0:  # double fork: the guard is nobody's child here, so a kill of this process tree spares it
        try:
            os.close(w)
            os.setsid()
            for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
                signal.signal(sig, signal.SIG_IGN)
            if os.fork() == 0:
                while os.read(r, 64):
                    pass
                _kill_tagged(tag)
        finally:
            os._exit(0)
    os.close(r)
    os.waitpid(child, 0)
    return w


def _reap():
    while True:
        try:
            if os.waitpid(-1, os.WNOHANG)[0] == 0:
                return
        except ChildProcessError:
            return


class Cluster:
    def __init__(self, folder):
        self.dir = folder
        self.procs = {}
        self.env = dict(os.environ, SLURM_CONF=os.path.join(folder, "slurm.conf"))
        self.node = socket.gethostname().split(".")[0]
        self.tag = ("SLURM_CONF=" + self.env["SLURM_CONF"]).encode()
        self.guard = None

    def path(self, name):
        return os.path.join(self.dir, name)

    def run(self, args, check=True, timeout=60, **kw):
        r = subprocess.run(args, env=kw.pop("env", self.env), capture_output=True, text=True, timeout=timeout, **kw)
        if check and r.returncode != 0:
            raise RuntimeError(f"{' '.join(args)} exited {r.returncode}: {r.stdout}{r.stderr}")
        return r

    def log_tail(self, lines=15):
        out = []
        for name in DAEMONS:
            try:
                with open(self.path(name + ".log")) as f:
                    out.append(f"--- {name}.log (last lines)\n" + "".join(f.readlines()[-lines:]))
            except OSError:
                pass
        return "\n".join(out)

    def _write_conf(self):
        # This machine as slurmd sees it: CPUs, sockets, cores, threads, memory ("NodeName=... CPUs=2 ...").
        hw = self.run(["slurmd", "-C"]).stdout.splitlines()[0].split()
        hw = " ".join(w for w in hw if not w.startswith(("NodeName=", "UpTime=")))
        d = self.dir
        conf = f"""# written by tests/programs/slurm/cluster.py: one node, localhost only, everything under {d}
ClusterName=aliaslabtest
SlurmctldHost={self.node}(127.0.0.1)
SlurmctldPort={_free_port()}
SlurmdPort={_free_port()}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket={d}/munge.sock
CredType=cred/munge
StateSaveLocation={d}/state
SlurmdSpoolDir={d}/spool
SlurmctldPidFile={d}/slurmctld.pid
SlurmdPidFile={d}/slurmd.pid
SlurmctldLogFile={d}/slurmctld.log
SlurmdLogFile={d}/slurmd.log
PlugStackConfig={d}/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc={d}/jobcomp.txt
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/backfill
SchedulerParameters=sched_interval=1
MpiDefault=none
SwitchType=switch/none
ReturnToService=2
JobRequeue=1
MinJobAge=3600
KillWait=5
SlurmctldTimeout=30
SlurmdTimeout=30
NodeName={self.node} NodeAddr=127.0.0.1 {hw} State=UNKNOWN
PartitionName=test Nodes={self.node} Default=YES MaxTime=INFINITE State=UP
"""
        with open(self.path("slurm.conf"), "w") as f:
            f.write(conf)
        open(self.path("plugstack.conf"), "w").close()
        for sub in ("state", "spool"):
            os.makedirs(self.path(sub), exist_ok=True)
        fd = os.open(self.path("munge.key"), os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600)
        os.write(fd, os.urandom(1024))
        os.close(fd)

    def _start(self, name, args):
        log = open(self.path(name + ".log"), "ab")
        self.procs[name] = subprocess.Popen(args, env=self.env, stdin=subprocess.DEVNULL, stdout=log,
                                            stderr=subprocess.STDOUT, preexec_fn=_die_with_parent)
        log.close()

    def _wait(self, what, ok, timeout=60):
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            for name, p in self.procs.items():
                if p.poll() is not None:
                    raise RuntimeError(f"{name} exited ({p.returncode}) while waiting for {what}\n{self.log_tail()}")
            if ok():
                return
            time.sleep(0.2)
        raise RuntimeError(f"timed out waiting for {what}\n{self.log_tail()}")

    def __enter__(self):
        if os.getpid() != 1:  # as a PID namespace's init, the kernel is the guard
            self.guard = _start_guard(self.tag)
        _libc.prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0)
        os.chmod(self.dir, 0o711)  # munged wants its socket's folder searchable
        try:
            self._write_conf()
            d = self.dir
            self._start("munged", ["munged", "-F", "--force", f"--key-file={d}/munge.key", f"--socket={d}/munge.sock",
                                   f"--pid-file={d}/munged.pid", f"--seed-file={d}/munged.seed"])
            self._wait("munged's socket", lambda: os.path.exists(self.path("munge.sock")))
            self._start("slurmctld", ["slurmctld", "-D", "-i"])
            self._wait("slurmctld", lambda: self.run(["scontrol", "ping"], check=False).stdout.find("UP") >= 0)
            self._start("slurmd", ["slurmd", "-D", "-N", self.node])
            self._wait("an idle node", lambda: self.run(["sinfo", "-h", "-N", "-o", "%T"], check=False).stdout.strip()
                       == "idle")
        except BaseException:
            self.stop()
            raise
        return self

    def __exit__(self, *exc):
        self.stop()

    def stop(self):
        """Cancel every job, stop the daemons (TERM, then KILL), kill whatever is left below this process."""
        if "slurmctld" in self.procs and self.procs["slurmctld"].poll() is None:
            try:
                self.run(["scancel", "--quiet", "--user", pwd.getpwuid(os.getuid()).pw_name], check=False, timeout=15)
                end = time.monotonic() + 15
                while time.monotonic() < end and self.run(["squeue", "-h"], check=False, timeout=15).stdout.strip():
                    time.sleep(0.2)
            except (OSError, subprocess.SubprocessError):
                pass
        for name in reversed(DAEMONS):
            p = self.procs.get(name)
            if p is None or p.poll() is not None:
                continue
            p.terminate()
            try:
                p.wait(timeout=15)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait()
        for _ in range(3):
            left = _descendants(os.getpid())
            for pid in left:
                try:
                    os.kill(pid, signal.SIGKILL)
                except ProcessLookupError:
                    pass
            time.sleep(0.2)
            _reap()
        _kill_tagged(self.tag)
        _reap()
        self.procs = {}
        if self.guard is not None:
            os.close(self.guard)
            self.guard = None

    def leftovers(self):
        """Descriptions of processes still running below this process (none after stop())."""
        out = []
        for pid in _descendants(os.getpid()):
            try:
                with open(f"/proc/{pid}/cmdline", "rb") as f:
                    cmd = f.read().replace(b"\0", b" ").decode(errors="replace")
                out.append(f"{pid} {cmd}")
            except OSError:
                pass
        return out
