#!/usr/bin/env python3
"""docs/batch.md's shares job array on a real single-node Slurm cluster, a task cancelled midway.

Usage: run_slurm_cluster.py PAGE MATEVO WORK_FOLDER  (PAGE: the batch page in docs)

The cluster (Debian's slurm-wlm and munge) lives in a temporary folder and stops at the end,
whatever happens: its own munge key and munged socket, a slurm.conf with free localhost ports,
this host as the one node (2 CPUs), process tracking without cgroups, no systemd, run as root as
in CI. On it, as the page says: the shares job array (docs/examples/shares.sbatch, which must be
the page's script) and the merge job waiting for it; task 3 is cancelled with scancel once it
has written its first block and before its last; the page's rerun lines resubmit it (it must
resume: keep the partial share's blocks) and the merge. Then the merged set must be byte for byte the set one process writes for the same
request. `matevo` is the small-size wrapper of run_batch_examples.py.
"""
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from run_batch_examples import examples, files_under, write_wrapper

CANCELLED_TASK = 3    # the task the page's rerun lines resubmit
BLOCKS_OF_TASK = 3    # its blocks: 3, 11 and 19 of the 20
NODE_CPUS = 2
# Added to the page's commands: small renders on the CPU back end, still large enough that a
# block takes a visible moment.
ADDED = {"variants": ["--size", "64", "--fitness-size", "32", "--backend", "cpu"]}


def free_ports(count):
    sockets = [socket.socket() for _ in range(count)]
    for s in sockets:
        s.bind(("127.0.0.1", 0))
    ports = [s.getsockname()[1] for s in sockets]
    for s in sockets:
        s.close()
    return ports


def wait_for(condition, what, timeout, poll=0.2):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        result = condition()
        if result:
            return result
        time.sleep(poll)
    raise RuntimeError(f"timed out after {timeout} s waiting for {what}")


class SlurmCluster:
    """munged, slurmctld and slurmd as child processes, configured in `folder`."""

    def __init__(self, folder):
        self.folder = folder
        self.node = socket.gethostname().split(".")[0]
        self.conf = folder / "slurm.conf"
        self.env = dict(os.environ, SLURM_CONF=str(self.conf))
        self.daemons = []

    def start(self):
        # munged refuses a socket in a folder others cannot enter.
        self.folder.chmod(0o755)
        for name in ("state", "spool", "log", "munge"):
            (self.folder / name).mkdir(mode=0o755)
        munge = self.folder / "munge"
        key = os.open(munge / "munge.key", os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o400)
        os.write(key, os.urandom(1024))
        os.close(key)
        socket_path = munge / "munge.socket"
        self.spawn("munged", ["munged", "--foreground", f"--socket={socket_path}",
                              f"--key-file={munge / 'munge.key'}",
                              f"--pid-file={munge / 'munged.pid'}",
                              f"--log-file={self.folder / 'log/munged.log'}",
                              f"--seed-file={munge / 'munged.seed'}"])
        wait_for(socket_path.exists, "munged's socket", 30)
        self.conf.write_text(self.configuration(socket_path))
        self.spawn("slurmctld", ["slurmctld", "-D", "-f", str(self.conf)])
        self.spawn("slurmd", ["slurmd", "-D", "-f", str(self.conf), "-N", self.node])
        wait_for(lambda: self.slurm(["sinfo", "-h", "-n", self.node, "-o", "%T"],
                                    check=False).strip() == "idle",
                 f"node {self.node} to be idle", 60)

    def configuration(self, munge_socket):
        controller_port, node_port = free_ports(2)
        folder = self.folder
        return f"""\
ClusterName=matevo-ci
SlurmctldHost={self.node}(127.0.0.1)
SlurmctldPort={controller_port}
SlurmdPort={node_port}
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket={munge_socket}
CredType=cred/munge
StateSaveLocation={folder / 'state'}
SlurmdSpoolDir={folder / 'spool'}
SlurmctldPidFile={folder / 'slurmctld.pid'}
SlurmdPidFile={folder / 'slurmd.pid'}
SlurmctldLogFile={folder / 'log/slurmctld.log'}
SlurmdLogFile={folder / 'log/slurmd.log'}
# No cgroups and no systemd in CI: processes tracked by parentage, no task binding.
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU_Memory
MpiDefault=none
ReturnToService=2
KillWait=10
NodeName={self.node} NodeAddr=127.0.0.1 CPUs={NODE_CPUS} RealMemory=2048 State=UNKNOWN
PartitionName=ci Nodes={self.node} Default=YES MaxTime=INFINITE State=UP
"""

    def spawn(self, name, command):
        log = open(self.folder / "log" / f"{name}.out", "wb")
        self.daemons.append((name, subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT,
                                                    env=self.env)))

    def slurm(self, command, cwd=None, check=True):
        result = subprocess.run(command, cwd=cwd, env=self.env, capture_output=True, text=True,
                                timeout=60)
        if check and result.returncode != 0:
            raise RuntimeError(f"{' '.join(command)}: exit {result.returncode}: {result.stderr}")
        return result.stdout

    def job_field(self, job, name):
        for field in self.slurm(["scontrol", "-o", "show", "job", job]).split():
            if field.startswith(name + "="):
                return field.split("=", 1)[1]
        raise RuntimeError(f"no {name} for job {job}")

    def job_state(self, job):
        return self.job_field(job, "JobState")

    def matevo_of(self, job):
        """The pid of the matevo process of a running job (or array task), or None."""
        job_id = self.job_field(job, "JobId")  # listpids takes no array task names
        for line in self.slurm(["scontrol", "listpids", job_id], check=False).splitlines()[1:]:
            pid = line.split()[0]
            try:
                if Path(f"/proc/{pid}/comm").read_text().strip() == "matevo":
                    return int(pid)
            except OSError:
                pass
        return None

    def queue_empty(self):
        """Whether every job has ended; raises for one that never will (a failed dependency)."""
        queue = self.slurm(["squeue", "-h", "-o", "%i %r"], check=False).splitlines()
        for line in queue:
            if line.endswith(" DependencyNeverSatisfied"):
                raise RuntimeError(f"job {line.split()[0]}: a job it waits for failed")
        return not queue

    def stop(self):
        """Cancels every job, then stops the daemons in reverse order; never raises."""
        try:
            if any(name == "slurmctld" and daemon.poll() is None for name, daemon in self.daemons):
                self.slurm(["scancel", "--user", "root"], check=False)
                wait_for(self.queue_empty, "the cancelled jobs to end", 60)
        except (RuntimeError, subprocess.SubprocessError) as error:
            print(f"slurm cluster: {error}", file=sys.stderr)
        for name, daemon in reversed(self.daemons):
            daemon.terminate()
            try:
                daemon.wait(timeout=30)
            except subprocess.TimeoutExpired:
                daemon.kill()
                daemon.wait()

    def logs(self):
        text = ""
        for log in sorted((self.folder / "log").iterdir()):
            lines = log.read_text(errors="replace").splitlines()[-15:]
            text += f"--- {log.name}\n" + "\n".join(lines) + "\n"
        return text


def bash(script, cwd, env):
    result = subprocess.run(["bash", "-c", script], cwd=cwd, env=env, capture_output=True,
                            text=True, timeout=600)
    if result.returncode != 0:
        raise RuntimeError(f"{script}\nexit {result.returncode}: {result.stdout}{result.stderr}")
    return result.stdout.split()


def block_written(shares, block):
    """Whether block's contact sheet is anywhere under shares, its share's staging folder
    included (which may vanish while it is searched)."""
    try:
        return any(shares.rglob(f"block_{block:03d}.png"))
    except OSError:
        return False


def run_on_cluster(cluster, found, sbatch_file, folder, env):
    """The page's job array, task 3 cancelled midway and rerun, and the merge; returns the
    merge job's id."""
    task_env = dict(env, SLURM_CONF=cluster.env["SLURM_CONF"])
    shutil.copy(sbatch_file, folder / "shares.sbatch")
    jobid, merge = bash(found["slurm-submit"] + 'echo "$jobid" "$merge"\n', folder, task_env)
    task = f"{jobid}_{CANCELLED_TASK}"

    # Midway, for certain: once the task's first block is written, its matevo is stopped
    # (SIGSTOP) before scancel, which sends SIGCONT and then SIGTERM, as for any job.
    def running_matevo():
        state = cluster.job_state(task)
        if state not in ("PENDING", "CONFIGURING", "RUNNING"):
            raise RuntimeError(f"task {task} ended {state} before it could be cancelled")
        return cluster.matevo_of(task) if state == "RUNNING" else None

    matevo = wait_for(running_matevo, f"task {task}'s matevo", 300)
    shares = folder / "shares"

    def first_block_written():
        if Path(f"/proc/{matevo}").exists():
            return block_written(shares, CANCELLED_TASK)
        raise RuntimeError(f"task {task}'s matevo ended before it could be cancelled")

    wait_for(first_block_written, f"task {task}'s first block", 120, poll=0.01)
    os.kill(matevo, signal.SIGSTOP)
    cluster.slurm(["scancel", task])
    # The task is CANCELLED at once; its matevo still writes the partial share before it ends.
    wait_for(lambda: not Path(f"/proc/{matevo}").exists(), f"task {task}'s matevo to end", 60)
    if cluster.job_state(task) != "CANCELLED":
        raise RuntimeError(f"task {task} ended {cluster.job_state(task)}, not CANCELLED")
    share = shares / str(CANCELLED_TASK)
    report = json.loads((share / "report.json").read_text())
    if report.get("partial") is not True:
        raise RuntimeError(f"{share}: not partial: task {task} ended before it was cancelled")
    print(f"slurm cluster: task {task} cancelled midway, "
          f"{sum(block['met'] for block in report['blocks'])} block(s) complete")

    rerun_script = (f"jobid={jobid}\nmerge={merge}\n" + found["slurm-rerun"] +
                    'echo "$rerun" "$merge"\n')
    rerun, merge = bash(rerun_script, folder, task_env)
    wait_for(cluster.queue_empty, "every job to end", 300)
    kept = BLOCKS_OF_TASK - len(report["missing_blocks"])
    resumed = f"resuming share {CANCELLED_TASK}/8 in shares/{CANCELLED_TASK}: {kept} block(s) kept"
    if resumed not in (folder / f"slurm-{rerun}_{CANCELLED_TASK}.out").read_text():
        raise RuntimeError(f"the rerun of task {task} did not say '{resumed}'")
    return merge


def main():
    page, matevo, work = Path(sys.argv[1]), Path(sys.argv[2]).resolve(), Path(sys.argv[3])
    work = work.resolve()  # the jobs run in another folder, with the wrapper's folder on PATH
    sbatch_file = page.parent / "examples" / "shares.sbatch"
    found = examples(page)
    for name in ("slurm-shares", "slurm-submit", "slurm-rerun", "one-run"):
        if name not in found:
            sys.exit(f"{page}: no example '{name}'")
    if found["slurm-shares"] != sbatch_file.read_text():
        sys.exit(f"{page}: the example 'slurm-shares' is not {sbatch_file}")
    for daemon in ("munged", "slurmctld", "slurmd", "sbatch"):
        if not shutil.which(daemon):
            sys.exit(f"no {daemon}: scripts/install-deps.sh --tests installs slurm-wlm and munge")

    shutil.rmtree(work, ignore_errors=True)
    write_wrapper(work / "bin", matevo, ADDED)
    env = dict(os.environ, PATH=f"{work / 'bin'}:{os.environ['PATH']}")
    started = time.monotonic()
    # A test driver's timeout ends the test with SIGTERM: the cluster still stops (finally).
    signal.signal(signal.SIGTERM, lambda *_: sys.exit("slurm cluster: terminated"))
    # Short: munged's socket path must fit a sockaddr_un.
    cluster = SlurmCluster(Path(tempfile.mkdtemp(prefix="matevo-slurm-")))
    on_cluster = work / "slurm"
    on_cluster.mkdir()
    try:
        cluster.start()
        merge = run_on_cluster(cluster, found, sbatch_file, on_cluster, env)
        if cluster.job_state(merge) != "COMPLETED":
            raise RuntimeError(f"merge job {merge} ended {cluster.job_state(merge)}")
    except (RuntimeError, OSError, ValueError, subprocess.SubprocessError) as error:
        outputs = "".join(f"--- {out.name}\n{out.read_text()}"
                          for out in sorted(on_cluster.glob("slurm-*.out")))
        sys.exit(f"slurm cluster: {error}\n{outputs}{cluster.logs()}")
    finally:
        cluster.stop()
        shutil.rmtree(cluster.folder, ignore_errors=True)
    print(f"slurm cluster: starting it, the job array, the rerun and the merge job took "
          f"{time.monotonic() - started:.0f} s")

    one_run = work / "one-run"
    one_run.mkdir()
    bash(found["one-run"], one_run, env)
    merged, whole = files_under(on_cluster / "world_set"), files_under(one_run / "world_set")
    if not whole:
        sys.exit("one-run: wrote nothing")
    if merged != whole:
        differing = sorted(set(merged) ^ set(whole)) or \
            [name for name in whole if merged[name] != whole[name]]
        sys.exit(f"the set merged on the cluster differs from one run: {differing[:3]}")
    print(f"slurm cluster: the merged set ({len(whole)} files) is byte for byte one run's")
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
