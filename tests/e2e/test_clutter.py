"""A default run leaves in the working folder what RTF 2.x's runner did, result.txt, and no more
(issue 38, item 13): rtf-logs/ only when a world's process printed something, rtf-attachments/
only when something is attached. Run from the suite's folder with relative paths."""
from conftest import marked, run_runner

SUITE = """<suite name="s">
  <fixture type="process">world.xml</fixture>
  <test type="exec">ok.sh</test>
</suite>
"""


def write_suite(folder, command):
    (folder / "world.xml").write_text(f"""<world name="quiet">
  <process name="server" command="{command}"/>
</world>
""")
    (folder / "s.xml").write_text(SUITE)
    (folder / "ok.sh").write_text("#!/bin/sh\nexit 0\n")
    (folder / "ok.sh").chmod(0o755)


def test_a_quiet_run_leaves_only_result_txt(tmp_path, marker):
    write_suite(tmp_path, "/bin/sleep 30")
    for isolation in ("process", "none"):
        run = run_runner("--suite", "s.xml", "--isolation", isolation, cwd=tmp_path,
                         env=marked(marker))
        assert run.returncode == 0 and "1 passed, 0 failed" in run.stdout, run
        left = sorted(p.name for p in tmp_path.iterdir())
        assert left == ["ok.sh", "result.txt", "s.xml", "world.xml"], (isolation, left)


def test_a_process_that_prints_leaves_its_log_and_its_attachment(tmp_path, marker):
    write_suite(tmp_path, "/bin/sh -c 'echo listening; exec sleep 30'")
    run = run_runner("--suite", "s.xml", cwd=tmp_path, env=marked(marker))
    assert run.returncode == 0, run
    assert (tmp_path / "rtf-logs" / "quiet" / "server.log").read_text() == "listening\n"
    attached = [p.name for p in (tmp_path / "rtf-attachments").iterdir()
                if not p.name.startswith(".")]
    assert attached == ["1-server.log"], attached
