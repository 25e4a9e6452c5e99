"""Two runs of the runner started at the same time in one folder, with the same world writing
its logs (logdir): each run writes a log of its own, says so when it took another name, and
attaches its own world's lines alone. They wrote one log file at once, each emptying the
other's, and a run's report attached lines of the other run's world. A report file another run
wrote while this one ran is replaced with a warning (it was replaced without a word). Loopback
only; nothing is left behind."""
import json

import pytest

from conftest import finish_runner, leftover_processes, marked, start_runner


def attached_logs(folder, report):
    """The text of each log the JSON report attaches (copies in rtf-attachments/)."""
    text = (folder / report).read_text()
    names = [word.split(" (log of process")[0]
             for word in text.split('"message":"')[1:] if " (log of process lab)" in
             word.split('"', 1)[0]]
    return [(folder / name).read_text() for name in names]


@pytest.mark.parametrize("scope", ["run", "suite"])
def test_two_runs_in_one_folder_write_and_attach_their_own_world_logs(tmp_path, marker, scope):
    shared = ' scope="run"' if scope == "run" else ""
    (tmp_path / "lab.xml").write_text("""<world name="lab" logdir="logs">
  <process name="lab" command="sh -c 'echo ready; echo tag-$RUN_TAG; while :; do sleep 0.05; done'">
    <ready timeout="20s"><output>ready</output></ready>
  </process>
</world>
""")
    (tmp_path / "arm.xml").write_text(f"""<suite name="arm">
  <fixture type="process"{shared}>lab.xml</fixture>
  <test type="exec" param="1.5">/bin/sleep</test>
</suite>
""")
    runs = {tag: start_runner("-s", "arm.xml", "-o", f"json:{tag}.json", cwd=tmp_path,
                              env=marked(marker, RUN_TAG=tag))
            for tag in ("one", "two")}
    outputs = {}
    for tag, proc in runs.items():
        status, out, err = finish_runner(proc, timeout=60)
        output = out + err
        assert status == 0, output
        outputs[tag] = output
    logs = sorted(path.name for path in (tmp_path / "logs").iterdir())
    assert logs == ["lab-2.log", "lab.log"], logs
    # Each log holds one world's lines, whole.
    texts = sorted((tmp_path / "logs" / name).read_text() for name in logs)
    assert texts == ["ready\ntag-one\n", "ready\ntag-two\n"], texts
    # Each report attaches its own world's log, and the run that took the other name says so.
    for tag in ("one", "two"):
        json.loads((tmp_path / f"{tag}.json").read_text())
        assert attached_logs(tmp_path, f"{tag}.json") == [f"ready\ntag-{tag}\n"]
    said = [tag for tag in ("one", "two")
            if "of 'lab' is written by another run: this one writes" in
            (tmp_path / f"{tag}.json").read_text()]
    assert len(said) == 1, outputs
    assert not leftover_processes(marker)


def test_a_report_another_run_wrote_meanwhile_is_not_replaced_silently(tmp_path, marker):
    """Two runs with the default output (result.txt): the one that ends last says it replaces
    the other's report; the other, and a run alone, say nothing."""
    (tmp_path / "long.xml").write_text(
        '<suite name="long">\n  <test type="exec" param="2.5">/bin/sleep</test>\n</suite>\n')
    (tmp_path / "short.xml").write_text(
        '<suite name="short">\n  <test type="exec" param="0.2">/bin/sleep</test>\n</suite>\n')
    warning = "warning: the text output result.txt was written by another run while this one ran"
    runs = {name: start_runner("-s", f"{name}.xml", cwd=tmp_path, env=marked(marker))
            for name in ("long", "short")}
    outputs = {}
    for name, proc in runs.items():
        status, out, err = finish_runner(proc, timeout=60)
        outputs[name] = out + err
        assert status == 0, outputs[name]
    assert warning in outputs["long"] and ": this run's replaces it" in outputs["long"], outputs
    assert warning not in outputs["short"], outputs
    assert "Suite long: passed" in (tmp_path / "result.txt").read_text()
    status, out, err = finish_runner(start_runner("-s", "short.xml", cwd=tmp_path,
                                                  env=marked(marker)), timeout=60)
    alone = out + err
    assert status == 0 and "warning" not in alone, alone
    assert not leftover_processes(marker)
