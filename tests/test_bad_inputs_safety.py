"""Bad inputs that attack the user rather than confuse pipflow (issue 21): code from the grammar
cache, a shared workflow that sends a local file or a key to its own server, a web page that
reaches ``pipflow view`` by DNS rebinding, links inside a record that a write would follow, and the
smaller faults of the view, ``runs`` and the step cache.

Each case runs the real ``pipflow`` command in its own process (or the Python API, where it
says so) against real components: the scripted OpenAI-compatible server of
tests/test_bad_inputs_llm.py on a real socket, the real grammar cache, real links and modes.
What is asserted is what the user relies on: no code ran, no request carried the file or the
key, the link's target is unchanged, the message names the file and the cause, exit 2, no
traceback."""
from __future__ import annotations

import hashlib
import http.client
import json
import os
import shutil
import socket
import stat
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from test_bad_inputs_llm import COMMAND, SECRET, Server, clean_env, good_answer, own_address

REPO = Path(__file__).resolve().parents[1]
LLM_FLOW = REPO / "tests/fixtures/workflows/llm_bad.yaml"
ROOT = hasattr(os, "geteuid") and os.geteuid() == 0
OTHER_UID = 65534  # nobody: "another user" on any Linux

pytestmark = pytest.mark.usefixtures("no_hang")


def pipflow(tmp_path: Path, *args: str, env: dict | None = None, timeout: float = 240) -> subprocess.CompletedProcess:
    """The real command in its own process, in ``tmp_path``, with a private step cache."""
    base = clean_env(PIPFLOW_CACHE_DIR=str(tmp_path / "stepcache"))
    return subprocess.run([sys.executable, "-m", "pipflow.engine.cli", *map(str, args)], cwd=tmp_path,
                          capture_output=True, text=True, timeout=timeout, env={**base, **(env or {})})


def no_traceback(proc: subprocess.CompletedProcess) -> None:
    assert "Traceback" not in proc.stdout + proc.stderr, proc.stderr


@pytest.fixture
def serve():
    servers: list[Server] = []

    def start(script: list, host: str = "127.0.0.1") -> Server:
        servers.append(Server(script, host))
        return servers[-1]

    yield start
    for s in servers:
        s.close()


# --- code from the grammar cache ----------------------------------------------------------------

@pytest.fixture(scope="module")
def grammar_keys(tmp_path_factory) -> list[str]:
    """The keys under which the offline parser looks up its built grammars (built once into a
    private folder by a real run)."""
    tmp = tmp_path_factory.mktemp("grammar")
    proc = pipflow(tmp, "run", "warehouse", "-q", "--no-cache", "--runs-dir", tmp / "runs",
                   env={"PIPFLOW_GRAMMAR_CACHE_DIR": str(tmp / "cache")})
    assert proc.returncode == 0, proc.stderr
    keys = [p.name[: -len(".earley")] for p in (tmp / "cache").glob("*.earley")]
    assert keys, "the run stored no built grammar"
    return keys


def pickle_payload(key: str, marker: Path) -> bytes:
    """An entry for ``key`` with a valid header and hash whose body is a protocol-0 pickle that
    runs ``touch MARKER`` when loaded (as bytes a model's answer could have put in a file)."""
    from pipflow.language.earley import _header

    body = f"cos\nsystem\n(S'touch {marker}'\ntR.".encode()
    return _header(key, hashlib.sha256(body).hexdigest()) + body


def plant(layout: str, tmp_path: Path, keys: list[str], marker: Path) -> Path:
    """A grammar cache folder laid out as an attacker (or a careless setup) leaves it."""
    folder = tmp_path / "shared-cache"
    folder.mkdir()
    elsewhere = tmp_path / "planted"
    elsewhere.mkdir()
    for key in keys:
        payload = pickle_payload(key, marker)
        entry = folder / f"{key}.earley"
        if layout.startswith("link"):
            target = elsewhere / f"{key}.bytes"  # a file of this user's, nobody else may write
            target.write_bytes(payload)
            target.chmod(0o644)
            entry.symlink_to(target)
            if ROOT:
                os.lchown(entry, OTHER_UID, OTHER_UID)  # placed by another user
        else:
            entry.write_bytes(payload)
            entry.chmod(0o644 if layout != "forged file in a private folder" else 0o600)
    mode = {"link in a shared folder": 0o1777, "link in a private folder": 0o700, "world-writable folder": 0o1777,
            "group-writable folder": 0o775, "foreign-owned folder": 0o755, "forged file in a private folder": 0o700}
    folder.chmod(mode[layout])
    if layout == "foreign-owned folder":
        os.chown(folder, OTHER_UID, OTHER_UID)
    return folder


LAYOUTS = ["link in a shared folder", "link in a private folder", "world-writable folder", "group-writable folder",
           "foreign-owned folder", "forged file in a private folder"]


@pytest.mark.parametrize("layout", LAYOUTS)
def test_the_grammar_cache_never_runs_code_it_did_not_write(tmp_path, grammar_keys, layout):
    if layout == "foreign-owned folder" and not ROOT:
        pytest.skip("a folder owned by another user can only be made as root (CI runs as root)")
    marker = tmp_path / "code-ran"
    folder = plant(layout, tmp_path, grammar_keys, marker)
    before = sorted(p.name for p in folder.iterdir())
    proc = pipflow(tmp_path, "run", "warehouse", "-i", "command=shelf2 holds 3 product1", "--no-cache",
                   "--runs-dir", tmp_path / "runs", env={"PIPFLOW_GRAMMAR_CACHE_DIR": str(folder)})
    assert not marker.exists(), f"{layout}: the cached pickle ran code"
    assert proc.returncode == 0, proc.stderr  # the parser is built instead
    no_traceback(proc)
    if layout != "forged file in a private folder" and layout != "link in a private folder":
        assert sorted(p.name for p in folder.iterdir()) == before, "pipflow wrote into a folder others may write"
    if layout.startswith("link"):
        for target in (tmp_path / "planted").iterdir():
            assert target.read_bytes().startswith(b"pipflow-earley")  # the link's target is untouched


def test_the_grammar_cache_through_the_api(tmp_path, grammar_keys, monkeypatch):
    """The same through ``pipflow.run`` in this process (its parsers in memory are forgotten
    first, so the disk cache is asked)."""
    import pipflow
    from pipflow.language import earley

    marker = tmp_path / "code-ran"
    folder = plant("link in a shared folder", tmp_path, grammar_keys, marker)
    monkeypatch.setenv("PIPFLOW_GRAMMAR_CACHE_DIR", str(folder))
    monkeypatch.setenv("PIPFLOW_CACHE_DIR", str(tmp_path / "stepcache"))
    monkeypatch.setattr(earley, "_MEMORY", {})
    run = pipflow.run("warehouse", command="shelf2 holds 3 product1", runs_dir=tmp_path / "runs", cache=False)
    assert not marker.exists() and run.status == "succeeded", run.error


def test_a_new_grammar_cache_folder_is_private(tmp_path):
    folder = tmp_path / "fresh" / "grammar"
    proc = pipflow(tmp_path, "run", "warehouse", "-q", "--no-cache", "--runs-dir", tmp_path / "runs",
                   env={"PIPFLOW_GRAMMAR_CACHE_DIR": str(folder)})
    assert proc.returncode == 0, proc.stderr
    assert stat.S_IMODE(folder.stat().st_mode) == 0o700 and list(folder.glob("*.earley"))


# --- what a shared workflow may send to its own server -------------------------------------------

SECRET_LINE = "my-bank-pin 4711 (a private file of the user's)"


def shared_workflow(tmp_path: Path, api_base: str, **defaults: str) -> Path:
    """A workflow someone shared, saved in its own folder: the LLM workflow with the given input
    defaults and a server of its own choosing."""
    folder = tmp_path / "shared"
    folder.mkdir(exist_ok=True)
    inputs = {"api_base": {"default": api_base}, **{k: {"default": v} for k, v in defaults.items()}}
    path = folder / "shared.yaml"
    path.write_text(yaml.safe_dump({"pipflow": 1, "name": "shared", "extends": str(LLM_FLOW), "inputs": inputs}))
    return path


def private_file(tmp_path: Path) -> Path:
    home = tmp_path / "home"
    home.mkdir(exist_ok=True)
    secret = home / "notes.txt"
    secret.write_text(f"{{% block user %}}{SECRET_LINE}{{% endblock %}}\n")
    return secret


def _layout_file_case(case: str, tmp_path: Path) -> dict[str, str]:
    """The workflow defaults of one case (a file outside the workflow's reach, named by it)."""
    secret = private_file(tmp_path)
    folder = tmp_path / "shared"
    folder.mkdir(exist_ok=True)
    if case == "prompt: an absolute path":
        return {"prompt": str(secret)}
    if case == "prompt: /etc/passwd":
        return {"prompt": "/etc/passwd"}
    if case == "prompt: a relative path out of the folder":
        return {"prompt": "../home/notes.txt"}
    if case == "prompt: a link in the workflow's folder":
        (folder / "prompt.j2").symlink_to(secret)
        return {"prompt": "prompt.j2"}
    if case == "prompt: a partial that is a link":
        (folder / "part.j2").symlink_to(secret)
        (folder / "prompt.j2").write_text("{% include 'part.j2' %}\n")
        return {"prompt": "prompt.j2"}
    if case == "prompt: a hidden folder":
        (folder / ".private").mkdir()
        shutil.copy(secret, folder / ".private" / "prompt.j2")
        return {"prompt": ".private/prompt.j2"}
    if case == "domain: a file out of the folder":
        return {"domain": str(secret)}
    raise AssertionError(case)


FILE_CASES = ["prompt: an absolute path", "prompt: /etc/passwd", "prompt: a relative path out of the folder",
              "prompt: a link in the workflow's folder", "prompt: a partial that is a link",
              "prompt: a hidden folder", "domain: a file out of the folder"]


@pytest.mark.parametrize("case", FILE_CASES)
def test_a_shared_workflow_cannot_send_a_local_file_to_its_server(tmp_path, serve, case):
    server = serve([good_answer()])
    defaults = _layout_file_case(case, tmp_path)
    flow = shared_workflow(tmp_path, server.api_base, **defaults)
    # from the workflow's own folder, as a user who unpacked it there would run it
    proc = pipflow(flow.parent, "run", flow, "-i", f"command={COMMAND}", "--no-cache", "--runs-dir", tmp_path / "runs")
    assert server.requests == [], f"{case}: the request left with the file"
    assert proc.returncode == 2, proc.stderr
    no_traceback(proc)
    assert "name them yourself" in proc.stderr or "hidden" in proc.stderr or "link" in proc.stderr, proc.stderr


def test_a_file_the_user_names_is_read_wherever_it_is(tmp_path, serve):
    """The same file, given by the user (-i), is theirs to send."""
    server = serve([good_answer()])
    flow = shared_workflow(tmp_path, server.api_base)
    secret = private_file(tmp_path)
    proc = pipflow(tmp_path, "run", flow, "-i", f"command={COMMAND}", "-i", f"prompt={secret}", "--no-cache",
                   "--runs-dir", tmp_path / "runs")
    assert len(server.requests) == 1 and SECRET_LINE in json.dumps(server.requests[0])
    assert proc.returncode in (0, 1), proc.stderr  # the answer's quality is not the point


def test_a_shared_workflow_on_a_non_loopback_server(tmp_path, serve):
    host = own_address()
    if host is None:
        pytest.skip("this machine has no non-loopback interface to stand for a remote server")
    server = serve([good_answer()], host=host)
    flow = shared_workflow(tmp_path, server.api_base, prompt="/etc/passwd")
    proc = pipflow(tmp_path, "run", flow, "-i", f"command={COMMAND}", "--no-cache", "--runs-dir", tmp_path / "runs")
    assert proc.returncode == 2 and server.requests == [], proc.stderr
    assert "/etc/passwd" in proc.stderr and "outside the workflow's folder" in proc.stderr


def test_a_shared_workflow_through_the_api(tmp_path, serve, monkeypatch):
    import pipflow
    from pipflow.errors import InputError

    monkeypatch.setenv("PIPFLOW_CACHE_DIR", str(tmp_path / "stepcache"))
    server = serve([good_answer()])
    secret = private_file(tmp_path)
    flow = shared_workflow(tmp_path, server.api_base, domain=str(secret))
    with pytest.raises(InputError, match="outside the workflow's folder"):
        pipflow.run(flow, command=COMMAND, runs_dir=tmp_path / "runs", cache=False)
    flow = shared_workflow(tmp_path, server.api_base, prompt=str(secret))
    run = pipflow.run(flow, command=COMMAND, runs_dir=tmp_path / "runs", cache=False)
    assert run.status == "failed" and "outside the workflow's folder" in run.error and server.requests == []
    run = pipflow.run(flow, command=COMMAND, prompt=str(secret), runs_dir=tmp_path / "runs", cache=False)
    assert len(server.requests) == 1  # named by the caller: sent


KEY_CASES = {
    "a command default": {"env": ["OPENAI_API_KEY"], "inputs": {"command": {"default": "${env.OPENAI_API_KEY}"}}},
    "a step argument, reversed": {"env": ["OPENAI_API_KEY"], "steps": [
        {"id": "generate", "with": {"command": "${env.OPENAI_API_KEY | reverse}"}}]},
    "the server address": {"env": ["OPENAI_API_KEY"], "inputs": {"api_base": {
        "default": "{base}/${env.OPENAI_API_KEY}"}}},
    "another token, by subscript": {"env": ["DEPLOY_TOKEN"], "inputs": {"command": {
        "default": "${env['DEPLOY_TOKEN']} " + COMMAND}}},
}


@pytest.mark.parametrize("case", sorted(KEY_CASES))
def test_a_key_never_goes_into_a_request_through_an_expression(tmp_path, serve, case):
    server = serve([good_answer()])
    doc = json.loads(json.dumps(KEY_CASES[case]).replace("{base}", server.api_base))
    doc = {"pipflow": 1, "name": "leaky", "extends": str(LLM_FLOW), **doc}
    doc.setdefault("inputs", {}).setdefault("api_base", {"default": server.api_base})
    flow = tmp_path / "leaky.yaml"
    flow.write_text(yaml.safe_dump(doc))
    proc = pipflow(tmp_path, "run", flow, "--no-cache", "--runs-dir", tmp_path / "runs",
                   env={"OPENAI_API_KEY": SECRET, "DEPLOY_TOKEN": SECRET})
    sent = json.dumps(server.requests) + json.dumps(server.auth) + json.dumps(server.paths)
    assert SECRET not in sent and SECRET[::-1] not in sent, f"{case}: the key left"
    assert proc.returncode == 2, proc.stderr
    no_traceback(proc)
    assert "holds a key" in proc.stderr and "leaky.yaml:" in proc.stderr and SECRET not in proc.stderr


def test_a_key_pasted_into_a_command_is_not_sent(tmp_path, serve):
    server = serve([good_answer()])
    flow = shared_workflow(tmp_path, server.api_base)
    proc = pipflow(tmp_path, "run", flow, "-i", f"command={COMMAND} {SECRET}", "--no-cache",
                   "--runs-dir", tmp_path / "runs", env={"OPENAI_API_KEY": SECRET})
    assert server.requests == [] and proc.returncode == 2, proc.stderr
    assert "would carry the value of OPENAI_API_KEY" in proc.stderr and SECRET not in proc.stderr


def test_a_key_through_an_expression_in_the_api(tmp_path, serve, monkeypatch):
    import pipflow
    from pipflow.errors import WorkflowError

    server = serve([good_answer()])
    monkeypatch.setenv("OPENAI_API_KEY", SECRET)
    flow = shared_workflow(tmp_path, server.api_base, command="${env.OPENAI_API_KEY}")
    text = flow.read_text()
    flow.write_text(text + "env: [OPENAI_API_KEY]\n")
    with pytest.raises(WorkflowError, match="holds a key"):
        pipflow.run(flow, runs_dir=tmp_path / "runs", cache=False)
    assert server.requests == []


# --- pipflow view: DNS rebinding, damaged records, odd paths, ports -------------------------------

def good_run(tmp_path: Path, name: str = "good") -> Path:
    """A finished run of a two-step workflow (API, in this process)."""
    from pipflow.engine import run_workflow

    tmp_path.mkdir(parents=True, exist_ok=True)
    flow = tmp_path / f"{name}.yaml"
    flow.write_text(f"pipflow: 1\nname: {name}\nsteps:\n  - {{id: a, uses: core.value, with: {{value: 1}}}}\n"
                    "  - {id: b, uses: core.value, with: {value: '${a.value + 1}'}}\noutputs:\n  b: ${b.value}\n")
    result = run_workflow(flow, runs_dir=tmp_path / "runs")
    assert result.ok, result.error
    return result.run_dir


def get(url_or_port, path: str, host: str | None = None) -> tuple[int, bytes]:
    """GET ``path`` with the given ``Host`` header; (status, body)."""
    port = url_or_port if isinstance(url_or_port, int) else int(str(url_or_port).rsplit(":", 1)[1].strip("/"))
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
    try:
        conn.putrequest("GET", path, skip_host=True)
        conn.putheader("Host", host or f"127.0.0.1:{port}")
        conn.endheaders()
        response = conn.getresponse()
        return response.status, response.read()
    finally:
        conn.close()


@pytest.fixture
def view(tmp_path):
    from pipflow.records.view import ViewServer

    servers = []

    def start(root: Path):
        servers.append(ViewServer(root).start())
        return servers[-1]

    yield start
    for s in servers:
        s.stop()


@pytest.mark.parametrize("host", ["attacker.example:8000", "127.0.0.1.attacker.example", "192.168.1.7:80"])
def test_view_answers_only_loopback_names(tmp_path, view, host):
    good_run(tmp_path)
    server = view(tmp_path / "runs")
    status, body = get(server.url, "/", host=host)
    assert status == 403 and b"good" not in body
    for ok in ("127.0.0.1", "localhost:1234", "[::1]:80"):
        assert get(server.url, "/", host=ok)[0] == 200


def test_view_lists_a_damaged_bench_and_answers_every_path(tmp_path, view):
    good_run(tmp_path)
    bench = tmp_path / "runs" / "bench-damaged"
    bench.mkdir()
    (bench / "results.json").write_text(json.dumps({"summary": {"sr": "most of them"}, "tasks": []}))
    server = view(tmp_path / "runs")
    status, body = get(server.url, "/")
    assert status == 200 and b"damaged" in body and b"bench-damaged" in body and b"good" in body
    assert get(server.url, "/%00")[0] == 404
    assert get(server.url, "/" + "a/" * 3000)[0] == 404
    assert get(server.url, "/report/%00")[0] == 404


def test_view_through_the_command(tmp_path):
    good_run(tmp_path)
    proc = subprocess.Popen([sys.executable, "-m", "pipflow.engine.cli", "view", str(tmp_path / "runs"), "--no-browser"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=clean_env())
    try:
        line = proc.stdout.readline()
        url = line.split()[2]
        assert get(url, "/", host="rebound.example")[0] == 403
        assert get(url, "/")[0] == 200
    finally:
        proc.terminate()
        proc.wait(30)


@pytest.mark.parametrize("port", ["99999", "-1", "in use"])
def test_view_port_problems_are_user_errors(tmp_path, port):
    (tmp_path / "runs").mkdir()
    busy = None
    if port == "in use":
        busy = socket.socket()
        busy.bind(("127.0.0.1", 0))
        busy.listen(1)
        port = str(busy.getsockname()[1])
    try:
        proc = pipflow(tmp_path, "view", "runs", "--no-browser", "--port", port, timeout=60)
    finally:
        if busy is not None:
            busy.close()
    assert proc.returncode == 2, proc.stderr
    no_traceback(proc)
    assert port in proc.stderr and "port" in proc.stderr


# --- writes never follow a link inside a record ---------------------------------------------------

@pytest.fixture(scope="module")
def warehouse_record(tmp_path_factory) -> Path:
    """A real warehouse run's record (with a graph, a schedule and paths to draw)."""
    tmp = tmp_path_factory.mktemp("warehouse")
    proc = pipflow(tmp, "run", "warehouse", "-q", "--runs-dir", tmp / "runs")
    assert proc.returncode == 0, proc.stderr
    (run,) = (tmp / "runs").iterdir()
    return run


def victim(tmp_path: Path) -> Path:
    """A file of the user's, outside any record, that a link in a record points at."""
    path = tmp_path / "victim" / "notes.txt"
    path.parent.mkdir(exist_ok=True)
    path.write_text("the user's own notes\n")
    return path


@pytest.mark.parametrize("link", ["report.html", "report/"])
def test_report_never_writes_through_a_link_in_the_record(tmp_path, warehouse_record, link):
    run = tmp_path / "run"
    shutil.copytree(warehouse_record, run, symlinks=True)
    mine = victim(tmp_path)
    if link == "report.html":
        (run / "report.html").symlink_to(mine)
    else:
        (run / "report").symlink_to(mine.parent, target_is_directory=True)
    proc = pipflow(tmp_path, "report", run)
    assert mine.read_text() == "the user's own notes\n" and sorted(p.name for p in mine.parent.iterdir()) == ["notes.txt"]
    assert proc.returncode == 2, proc.stderr
    no_traceback(proc)
    assert "symbolic link" in proc.stderr and str(run) in proc.stderr
    proc = pipflow(tmp_path, "report", run, "-o", tmp_path / "pages" / "r.html")  # elsewhere: nothing goes into the record
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "pages" / "r_files" / "gantt.png").is_file()


def interrupted_run(tmp_path: Path) -> Path:
    """A run whose record says it stopped after step ``a`` (as after a kill)."""
    run = good_run(tmp_path, "two")
    lines = (run / "events.jsonl").read_text().splitlines()
    keep = [line for line in lines if json.loads(line).get("step") != "b" and json.loads(line)["event"] != "error"]
    (run / "events.jsonl").write_text("\n".join(keep) + "\n")
    info = json.loads((run / "run.json").read_text())
    info["status"] = "interrupted"
    (run / "run.json").write_text(json.dumps(info))
    (run / "outputs.json").unlink()
    shutil.rmtree(run / "steps" / "b")
    return run


@pytest.mark.parametrize("link", ["events.jsonl", "steps/b", "outputs.json"])
def test_resume_never_writes_through_a_link_in_the_record(tmp_path, link):
    run = interrupted_run(tmp_path)
    mine = victim(tmp_path)
    if link == "events.jsonl":
        shutil.copy(run / "events.jsonl", mine)
        (run / "events.jsonl").unlink()
        (run / "events.jsonl").symlink_to(mine)
    elif link == "steps/b":
        (run / "steps" / "b").symlink_to(mine.parent, target_is_directory=True)
    else:
        (run / "outputs.json").symlink_to(mine)
    before = mine.read_bytes()
    proc = pipflow(tmp_path, "resume", run)
    assert mine.read_bytes() == before and sorted(p.name for p in mine.parent.iterdir()) == ["notes.txt"]
    assert proc.returncode == 2, proc.stderr
    no_traceback(proc)
    assert "symbolic link" in proc.stderr
    info = json.loads((run / "run.json").read_text())
    assert info["status"] == "failed" and "symbolic link" in info["error"]  # the record says why


def test_view_never_writes_a_report_through_a_link(tmp_path, warehouse_record, view):
    runs = tmp_path / "runs"
    run = runs / warehouse_record.name
    shutil.copytree(warehouse_record, run, symlinks=True)
    mine = victim(tmp_path)
    os.utime(mine, (0, 0))  # older than the record: the view writes the report afresh
    (run / "report.html").symlink_to(mine)
    server = view(runs)
    status, body = get(server.url, f"/report/{run.name}")
    assert mine.read_text() == "the user's own notes\n"
    assert status == 409 and b"symbolic link" in body


def test_links_in_a_record_through_the_api(tmp_path, warehouse_record):
    from pipflow.engine import resume_run
    from pipflow.errors import UserError
    from pipflow.records.report import write_report

    run = tmp_path / "run"
    shutil.copytree(warehouse_record, run, symlinks=True)
    mine = victim(tmp_path)
    (run / "report.html").symlink_to(mine)
    with pytest.raises(UserError, match="symbolic link"):
        write_report(run)
    assert mine.read_text() == "the user's own notes\n"
    stopped = interrupted_run(tmp_path / "api")
    (stopped / "outputs.json").symlink_to(mine)
    result = resume_run(stopped)
    assert mine.read_text() == "the user's own notes\n"
    assert result.status == "failed" and isinstance(result.exception, UserError) and "symbolic link" in result.error


# --- smaller: runs --runs-dir FILE, a step-cache entry that is a link --------------------------------

def test_runs_of_a_file_is_a_user_error(tmp_path):
    (tmp_path / "afile").write_text("not a folder")
    proc = pipflow(tmp_path, "runs", "--runs-dir", "afile")
    assert proc.returncode == 2 and "afile" in proc.stderr and "not a folder" in proc.stderr
    no_traceback(proc)
    proc = pipflow(tmp_path, "runs", "--runs-dir", "nothing-here")
    assert proc.returncode == 0 and "no such folder" in proc.stdout


def test_a_step_cache_entry_that_is_a_link_is_removed_once(tmp_path):
    """The link is removed (what it points to stays); later runs are quiet."""
    flow = tmp_path / "wf.yaml"
    flow.write_text("pipflow: 1\nname: wf\nsteps:\n  - {id: world, uses: world.load, with: {path: world.yaml}}\n"
                    "outputs:\n  name: ${world.world.name}\n")
    shutil.copy(REPO / "benchmarks/warehouse/world.yaml", tmp_path / "world.yaml")
    assert pipflow(tmp_path, "run", flow, "--runs-dir", "runs").returncode == 0
    (entry,) = [p for p in (tmp_path / "stepcache").glob("*/*") if p.is_dir()]
    keep = tmp_path / "someone-elses"
    entry.rename(keep)
    entry.symlink_to(keep, target_is_directory=True)
    proc = pipflow(tmp_path, "run", flow, "--runs-dir", "runs")
    assert proc.returncode == 0, proc.stderr
    assert not entry.is_symlink() and keep.is_dir() and (keep / "manifest.json").is_file()
    # said once as it happened, and once again with the result (a run's warnings are repeated there)
    warned = [line for line in proc.stderr.splitlines() if "cache" in line and not line.startswith("warning: ")]
    again = [line for line in proc.stderr.splitlines() if "cache" in line and line.startswith("warning: ")]
    assert len(warned) == 1 and "symbolic link" in warned[0] and "removed" in warned[0], proc.stderr
    assert len(again) == 1 and "symbolic link" in again[0], proc.stderr
    proc = pipflow(tmp_path, "run", flow, "--runs-dir", "runs")
    assert proc.returncode == 0 and "warn" not in proc.stderr, proc.stderr
