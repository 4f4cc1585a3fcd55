"""Full disks and read-only records (issue 21): the disk is the user's problem, and pipflow says so.

Expected of every write pipflow makes (run records, bench folders, reports): a disk that is full
(``ENOSPC``), over quota (``EDQUOT``), over the process's file size limit (``EFBIG``), read-only
(``EROFS``) or not writable (``EACCES``) is exit 2 with "no space left on DEVICE writing PATH" (or
"DEVICE is read-only ..."), no traceback; a run that fills the disk is marked failed with what it
did kept, and ``pipflow resume`` finishes it once there is space again; a disk full from the start
leaves no record that ``runs`` and ``resume`` could not use.

Two ways to fill a disk:
- **without root** (CI or not): a size limit on the ``pipflow`` process (``RLIMIT_FSIZE``, with
  SIGXFSZ ignored), under which a write past the limit fails with ``EFBIG``: the same path as
  ``ENOSPC`` through pipflow's one writer (engine/writes.py);
- **a real full tmpfs**, mounted for the test (root only: CI runs as root; where root cannot
  mount, the test fails saying why instead of skipping). Read-only records are a read-only bind
  mount as root, and a folder without write permission otherwise.
"""
from __future__ import annotations

import contextlib
import json
import os
import resource
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from test_bad_inputs_llm import clean_env

REPO = Path(__file__).resolve().parents[1]
TASKS = REPO / "benchmarks/warehouse/tasks.yaml"
ROOT = hasattr(os, "geteuid") and os.geteuid() == 0


def _can_mount() -> bool:
    """Root with CAP_SYS_ADMIN (bit 21 of the effective capabilities), which mounting needs: a
    container may run as root without it. Where that cannot be read, assume so and let the
    mount itself fail loudly."""
    if not ROOT:
        return False
    try:
        for line in Path("/proc/self/status").read_text().splitlines():
            if line.startswith("CapEff:"):
                return bool(int(line.split()[1], 16) >> 21 & 1)
    except (OSError, ValueError, IndexError):
        pass
    return True


CAN_MOUNT = _can_mount()

pytestmark = pytest.mark.usefixtures("no_hang")

GROW = """\
pipflow: 1
name: grow
inputs:
  size: {type: integer, default: 400000}
steps:
  - {id: a, uses: core.value, with: {value: small}}
  - {id: b, uses: core.value, with: {value: "${'x' * inputs.size}"}}
  - {id: c, uses: core.value, with: {value: "${b.value | length}"}}
outputs:
  n: ${c.value}
"""


def file_size_limit(limit: int):
    """``preexec_fn``: writes past ``limit`` bytes in any file fail with EFBIG (not a signal)."""
    def apply() -> None:
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
    return apply


def pipflow(cwd: Path, *args, limit: int | None = None, timeout: float = 300) -> subprocess.CompletedProcess:
    env = clean_env(PIPFLOW_CACHE_DIR=str(cwd / "stepcache"))
    return subprocess.run([sys.executable, "-m", "pipflow.engine.cli", *map(str, args)], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=timeout,
                          preexec_fn=file_size_limit(limit) if limit else None)


def no_traceback(proc: subprocess.CompletedProcess) -> None:
    assert "Traceback" not in proc.stdout + proc.stderr, proc.stderr


def records(runs: Path) -> list[Path]:
    return sorted(p for p in runs.iterdir() if p.is_dir()) if runs.is_dir() else []


# --- without root: a file size limit on the process ------------------------------------------------

def test_a_disk_that_fills_mid_run_fails_the_run_keeps_its_record_and_resumes(tmp_path):
    (tmp_path / "grow.yaml").write_text(GROW)
    proc = pipflow(tmp_path, "run", "grow.yaml", "--runs-dir", "runs", limit=150_000)
    assert proc.returncode == 2, proc.stderr
    no_traceback(proc)
    assert "no space left on" in proc.stderr and "ulimit -f" in proc.stderr
    (run,) = records(tmp_path / "runs")
    assert "step 'b'" in proc.stderr and str(run.relative_to(tmp_path) / "steps/b/outputs.json") in proc.stderr
    info = json.loads((run / "run.json").read_text())
    assert info["status"] == "failed" and "no space left on" in info["error"]
    assert json.loads((run / "steps" / "a" / "outputs.json").read_text()) == {"value": "small"}
    assert not (run / ".pipflow-reserve").exists()
    listed = pipflow(tmp_path, "runs", "--runs-dir", "runs")
    assert run.name in listed.stdout and "failed" in listed.stdout
    proc = pipflow(tmp_path, "resume", run, "--runs-dir", "runs")  # space again: it finishes
    assert proc.returncode == 0, proc.stderr
    assert json.loads((run / "outputs.json").read_text()) == {"n": 400_000}


def test_a_disk_full_from_the_start_leaves_no_half_record(tmp_path):
    (tmp_path / "grow.yaml").write_text(GROW)
    proc = pipflow(tmp_path, "run", "grow.yaml", "--runs-dir", "runs", limit=20_000)
    assert proc.returncode == 2, proc.stderr
    no_traceback(proc)
    assert "no space left on" in proc.stderr and "no run record was kept" in proc.stderr
    assert records(tmp_path / "runs") == []


def test_a_full_disk_through_the_api(tmp_path):
    """``pipflow.run`` in a script: the run comes back failed, naming the disk."""
    (tmp_path / "grow.yaml").write_text(GROW)
    script = ("import pipflow\n"
              "run = pipflow.run('grow.yaml', runs_dir='runs')\n"
              "print(run.status)\nprint(run.error)\n")
    proc = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, capture_output=True, text=True, timeout=300,
                          env=clean_env(PIPFLOW_CACHE_DIR=str(tmp_path / "stepcache")),
                          preexec_fn=file_size_limit(150_000))
    assert proc.returncode == 0, proc.stderr
    status, error = proc.stdout.splitlines()[:2]
    assert status == "failed" and "no space left on" in error


def test_a_bench_whose_runs_cannot_be_recorded_stops_with_exit_2(tmp_path):
    """Every run's record start needs its reserve: under a 40 kB limit none fits. The bench
    stops at once (not a table of failed runs), and completes after the limit is gone."""
    proc = pipflow(tmp_path, "bench", TASKS, "--jobs", "1", "--out", "out", "-q", limit=40_000)
    assert proc.returncode == 2, proc.stderr
    no_traceback(proc)
    assert "no space left on" in proc.stderr and "bench stopped" in proc.stderr
    proc = pipflow(tmp_path, "bench", TASKS, "--jobs", "2", "--out", "out", "-q", "--resume")
    assert proc.returncode == 0, proc.stderr
    results = json.loads((tmp_path / "out" / "results.json").read_text())
    assert results["summary"]["runs"] == 10


# --- as root: a real tmpfs that is full, or that fills ---------------------------------------------

@contextlib.contextmanager
def mounted_tmpfs(where: Path, size: str):
    """A tmpfs of ``size`` at ``where``; unmounted afterwards (whatever happens)."""
    if not CAN_MOUNT:
        pytest.skip("mounting a tmpfs needs root with CAP_SYS_ADMIN; test_a_disk_that_fills_mid_run... covers the "
                    "same path without it")
    where.mkdir(parents=True, exist_ok=True)
    proc = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(where)],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        pytest.fail(f"running as root, but `mount -t tmpfs` failed ({proc.stderr.strip()}): the real full-disk "
                    "tests need CAP_SYS_ADMIN (a container started without it cannot mount)")
    try:
        yield where
    finally:
        if subprocess.run(["umount", str(where)], capture_output=True).returncode != 0:
            subprocess.run(["umount", "-l", str(where)], capture_output=True)


def remount(where: Path, size: str) -> None:
    subprocess.run(["mount", "-o", f"remount,size={size}", str(where)], check=True)


def fill(where: Path) -> Path:
    """Fill a file system to the last byte; the filler file is returned (delete it to free)."""
    filler = where / "filler"
    with open(filler, "wb") as fh:
        try:
            while True:
                fh.write(b"\0" * 65536)
                fh.flush()
        except OSError:
            pass
    return filler


def test_a_full_tmpfs_from_the_start(tmp_path):
    (tmp_path / "grow.yaml").write_text(GROW)
    with mounted_tmpfs(tmp_path / "disk", "1m") as disk:
        (disk / "runs").mkdir()
        filler = fill(disk)
        proc = pipflow(tmp_path, "run", "grow.yaml", "--runs-dir", disk / "runs")
        assert proc.returncode == 2, proc.stderr
        no_traceback(proc)
        assert f"no space left on tmpfs mounted at {disk}" in proc.stderr
        assert records(disk / "runs") == []
        filler.unlink()
        proc = pipflow(tmp_path, "run", "grow.yaml", "--runs-dir", disk / "runs", "-i", "size=10")
        assert proc.returncode == 0, proc.stderr


def test_a_tmpfs_that_fills_mid_run_then_grows(tmp_path):
    (tmp_path / "grow.yaml").write_text(GROW)
    with mounted_tmpfs(tmp_path / "disk", "256k") as disk:
        proc = pipflow(tmp_path, "run", "grow.yaml", "--runs-dir", disk / "runs")
        assert proc.returncode == 2, proc.stderr
        no_traceback(proc)
        assert f"no space left on tmpfs mounted at {disk} writing" in proc.stderr
        (run,) = records(disk / "runs")
        info = json.loads((run / "run.json").read_text())
        assert info["status"] == "failed" and "no space left" in info["error"]
        assert (run / "steps" / "a" / "outputs.json").is_file()
        filler = fill(disk)  # the last bytes too: the report cannot go there; it says where it can
        proc = pipflow(tmp_path, "report", run)
        assert proc.returncode == 2 and "no space left on tmpfs" in proc.stderr and "-o FILE" in proc.stderr, proc.stderr
        no_traceback(proc)
        filler.unlink()
        remount(disk, "4m")
        proc = pipflow(tmp_path, "resume", run)
        assert proc.returncode == 0, proc.stderr
        assert json.loads((run / "outputs.json").read_text()) == {"n": 400_000}


def test_a_bench_out_on_a_tmpfs_that_fills(tmp_path):
    """Rows stored before the disk filled are kept; ``--resume`` completes the bench once the
    disk has room, and every record has its row."""
    with mounted_tmpfs(tmp_path / "disk", "700k") as disk:
        out = disk / "bench"
        proc = pipflow(tmp_path, "bench", TASKS, "--jobs", "1", "--out", out, "-q")
        assert proc.returncode == 2, proc.stderr
        no_traceback(proc)
        assert f"no space left on tmpfs mounted at {disk}" in proc.stderr
        kept = list((out / "runs").rglob("*.json")) if (out / "runs").is_dir() else []
        assert 0 < len(kept) < 10, kept
        remount(disk, "32m")
        proc = pipflow(tmp_path, "bench", TASKS, "--jobs", "2", "--out", out, "-q", "--resume")
        assert proc.returncode == 0, proc.stderr
        results = json.loads((out / "results.json").read_text())
        assert results["summary"]["runs"] == 10 and results["resumed_runs"] == len(kept)
        rows = json.loads((out / "runs.json").read_text())
        assert {Path(r["run_dir"]).name for r in rows} == {p.name for p in (out / "records").iterdir()}


# --- read-only records ----------------------------------------------------------------------------

@contextlib.contextmanager
def read_only(folder: Path):
    """``folder`` read-only: a read-only bind mount as root (root ignores modes), a folder
    without write permission otherwise."""
    if ROOT and not CAN_MOUNT:
        pytest.skip("root without CAP_SYS_ADMIN: no folder can be made read-only (root ignores modes, and a "
                    "read-only bind mount needs that capability)")
    if ROOT:
        subprocess.run(["mount", "--bind", str(folder), str(folder)], check=True)
        try:
            proc = subprocess.run(["mount", "-o", "remount,bind,ro", str(folder)], capture_output=True, text=True)
            if proc.returncode != 0:
                pytest.fail(f"running as root, but a read-only bind mount failed: {proc.stderr.strip()}")
            yield "read-only"
        finally:
            subprocess.run(["umount", str(folder)], capture_output=True)
        return
    modes = {p: p.stat().st_mode for p in [folder, *folder.rglob("*")]}
    for p in modes:
        p.chmod(modes[p] & ~0o222)
    try:
        yield "no permission"
    finally:
        for p, mode in modes.items():
            p.chmod(mode)


def stopped_run(tmp_path: Path) -> Path:
    """A run whose record says it was interrupted after its first step."""
    (tmp_path / "grow.yaml").write_text(GROW)
    proc = pipflow(tmp_path, "run", "grow.yaml", "--runs-dir", "runs", "-i", "size=5")
    assert proc.returncode == 0, proc.stderr
    (run,) = records(tmp_path / "runs")
    info = json.loads((run / "run.json").read_text())
    info["status"] = "interrupted"
    (run / "run.json").write_text(json.dumps(info))
    keep = [line for line in (run / "events.jsonl").read_text().splitlines() if json.loads(line).get("step") == "a"]
    (run / "events.jsonl").write_text("\n".join(keep) + "\n")
    (run / "outputs.json").unlink()
    return run


def test_report_and_resume_of_a_read_only_record(tmp_path):
    run = stopped_run(tmp_path)
    before = sorted(str(p.relative_to(run)) for p in run.rglob("*"))
    with read_only(run) as why:
        proc = pipflow(tmp_path, "report", run)
        assert proc.returncode == 2 and why in proc.stderr and "-o FILE" in proc.stderr, proc.stderr
        no_traceback(proc)
        proc = pipflow(tmp_path, "report", run, "-o", tmp_path / "pages" / "run.html")
        assert proc.returncode == 0, proc.stderr
        assert (tmp_path / "pages" / "run.html").is_file()
        (tmp_path / "folder").mkdir()
        proc = pipflow(tmp_path, "report", run, "-o", tmp_path / "folder")  # a folder: the page goes in it
        assert proc.returncode == 0 and (tmp_path / "folder" / "report.html").is_file(), proc.stderr
        proc = pipflow(tmp_path, "resume", run)
        assert proc.returncode == 2 and why in proc.stderr and str(run) in proc.stderr, proc.stderr
        no_traceback(proc)
    assert sorted(str(p.relative_to(run)) for p in run.rglob("*")) == before
    proc = pipflow(tmp_path, "resume", run)  # writable again: it finishes
    assert proc.returncode == 0, proc.stderr


def test_a_read_only_record_through_the_api(tmp_path):
    from pipflow.engine import resume_run
    from pipflow.errors import UserError
    from pipflow.records.report import write_report

    run = stopped_run(tmp_path)
    with read_only(run):
        with pytest.raises(UserError, match="-o FILE|read-only|permission"):
            write_report(run)
        assert write_report(run, tmp_path / "elsewhere.html").is_file()
        with pytest.raises(UserError):
            resume_run(run)
    assert resume_run(run).ok
