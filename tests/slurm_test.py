"""The shipped job-array script on a real one-node Slurm (Debian's slurm-wlm and munge): a
controller and a node daemon started here, stopped afterwards."""
import glob
import json
import os
import shutil
import signal
import socket
import subprocess
import time
import unittest

from support import SOURCE, TOOL, TempDirTest, info, run

SBATCH = os.path.join(SOURCE, "scripts", "slurm", "curvature_inpaint_array.sbatch")


class OneNodeSlurm:
    """slurmctld and slurmd for this machine alone, with their state in `root`."""

    def __init__(self, root):
        self.root = root
        self.conf = os.path.join(root, "slurm.conf")
        self.env = dict(os.environ, SLURM_CONF=self.conf)
        self.started = []

    def start(self):
        for d in ("state", "spool", "log"):
            os.makedirs(os.path.join(self.root, d), exist_ok=True)
        host = socket.gethostname().split(".")[0]
        memory = int(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2**20 * 0.8)
        with open(self.conf, "w") as f:
            f.write(f"""ClusterName=curvature-inpaint-test
SlurmctldHost={host}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
StateSaveLocation={self.root}/state
SlurmdSpoolDir={self.root}/spool
SlurmctldPidFile={self.root}/slurmctld.pid
SlurmdPidFile={self.root}/slurmd.pid
SlurmctldLogFile={self.root}/log/slurmctld.log
SlurmdLogFile={self.root}/log/slurmd.log
SlurmctldPort=6917
SlurmdPort=6918
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
NodeName={host} CPUs={os.cpu_count()} RealMemory={memory} State=UNKNOWN
PartitionName=test Nodes=ALL Default=YES MaxTime=INFINITE State=UP
""")
        with open(os.path.join(self.root, "cgroup.conf"), "w") as f:
            f.write("CgroupPlugin=cgroup/v1\nCgroupAutomount=no\n")
        # munge: the package's key; run as root, so its ownership checks are forced past.
        os.makedirs("/run/munge", exist_ok=True)
        if subprocess.run(["munge", "-n"], capture_output=True).returncode != 0:
            r = subprocess.run(["munged", "--force", "--key-file=/etc/munge/munge.key",
                                f"--log-file={self.root}/log/munged.log",
                                f"--pid-file={self.root}/munged.pid",
                                "--socket=/run/munge/munge.socket.2",
                                f"--seed-file={self.root}/munge.seed"], capture_output=True, text=True)
            if r.returncode != 0:
                raise RuntimeError("munged refused to start: " + r.stderr)
            self.started.append(os.path.join(self.root, "munged.pid"))
        for daemon in ("slurmctld", "slurmd"):
            r = subprocess.run([daemon, "-f", self.conf], capture_output=True, text=True, env=self.env)
            if r.returncode != 0:
                raise RuntimeError(f"{daemon} refused to start: {r.stderr}\n{self.log(daemon)}")
            self.started.append(os.path.join(self.root, daemon + ".pid"))
        deadline = time.time() + 60
        while time.time() < deadline:
            r = subprocess.run(["sinfo", "-h", "-o", "%t"], capture_output=True, text=True, env=self.env)
            if r.returncode == 0 and r.stdout.strip() in ("idle", "mix", "alloc"):
                return
            time.sleep(0.5)
        raise RuntimeError("the node never became idle:\n" + self.log("slurmctld") + self.log("slurmd"))

    def log(self, daemon):
        path = os.path.join(self.root, "log", daemon + ".log")
        return open(path).read()[-3000:] if os.path.exists(path) else ""

    def stop(self):
        subprocess.run(["scancel", "--full", "--user", "root"], capture_output=True, env=self.env)
        for pid_file in reversed(self.started):
            try:
                with open(pid_file) as f:
                    os.kill(int(f.read().strip()), signal.SIGTERM)
            except (OSError, ValueError):
                pass
        time.sleep(1)

    def sbatch(self, *args):
        r = subprocess.run(["sbatch", "--parsable", *args], capture_output=True, text=True, env=self.env)
        if r.returncode != 0:
            raise RuntimeError("sbatch: " + r.stderr)
        return r.stdout.strip().split(";")[0]

    def wait(self, job, timeout=600):
        deadline = time.time() + timeout
        while time.time() < deadline:
            r = subprocess.run(["squeue", "-h", "-j", job], capture_output=True, text=True, env=self.env)
            if r.returncode == 0 and not r.stdout.strip():
                return
            time.sleep(0.5)
        raise RuntimeError(f"job {job} still queued after {timeout} s")


@unittest.skipUnless(os.geteuid() == 0 and shutil.which("slurmctld"),
                     "a one-node Slurm needs root and Debian's slurm-wlm")
class JobArray(TempDirTest):
    def setUp(self):
        super().setUp()
        self.slurm = OneNodeSlurm(self.path("slurm"))
        self.addCleanup(self.slurm.stop)
        self.slurm.start()

    def submit(self, folder, out, *fill):
        return self.slurm.sbatch("--array=0-2", "--cpus-per-task=1", "--mem=1G",
                                 f"--output={self.path('task-%a.log')}",
                                 f"--export=ALL,CURVATURE_INPAINT={TOOL}", SBATCH, folder, out, *fill)

    def lines(self, out):
        lines = []
        for path in sorted(glob.glob(os.path.join(out, "results*.jsonl"))):
            with open(path) as f:
                lines += [json.loads(l) for l in f if l.strip()]
        return lines

    def test_an_array_of_three_fills_nine_scans_once(self):
        folder, out = self.collection(8, 700), self.path("out")
        with open(os.path.join(folder, "unreadable.ply"), "wb") as f:
            f.write(b"\x00\x01 not a mesh")
        job = self.submit(folder, out, "--fake-holes", "0", "--size", "64")
        self.slurm.wait(job)
        lines = self.lines(out)
        names = sorted(os.path.basename(l["input"]) for l in lines)
        self.assertEqual(names, sorted(os.listdir(folder)), "every scan once: " + str(names))
        self.assertEqual(sorted(os.path.basename(p) for p in glob.glob(os.path.join(out, "results*"))),
                         ["results.1-of-3.jsonl", "results.2-of-3.jsonl", "results.3-of-3.jsonl"])
        for l in lines:
            if l["input"].endswith("unreadable.ply"):
                self.assertEqual(l["status"], "failed")
                self.assertTrue(l["error"])
            else:
                self.assertEqual(l["status"], "ok", l)
                self.assertEqual(info(os.path.join(out, l["output"]))["holes"], 0)
        r = run([TOOL, "batch", "--summary", out])
        self.assertIn("| 9 | 8 | 1 | 8 | 0 |", r.stdout)

    def test_a_cancelled_array_resubmitted_completes_without_redoing(self):
        folder, out = self.collection(9, 700), self.path("out")
        job = self.submit(folder, out)  # with the validation: about a second a scan
        deadline = time.time() + 300
        while time.time() < deadline and len(self.lines(out)) < 2:
            time.sleep(0.1)
        subprocess.run(["scancel", job], env=self.slurm.env, check=True)
        self.slurm.wait(job)
        before = self.lines(out)
        self.assertLess(len(before), 9, "cancelled half-way")
        stamps = {l["output"]: os.stat(os.path.join(out, l["output"])).st_mtime_ns for l in before}
        self.slurm.wait(self.submit(folder, out))
        after = self.lines(out)
        self.assertEqual(sorted(l["output"] for l in after), sorted(os.listdir(folder)))
        self.assertEqual(len(after), 9, "nothing done twice")
        self.assertEqual(stamps, {n: os.stat(os.path.join(out, n)).st_mtime_ns for n in stamps})


if __name__ == "__main__":
    unittest.main()
