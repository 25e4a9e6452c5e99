"""Issue 38, friction 6: one count of failures everywhere. The summary said "2 failed" while
the closing line said "3 failed" (a fixture failure counted in one only)."""
import re

from conftest import run_runner


def test_the_summary_and_the_closing_line_count_the_same_failures(tmp_path):
    (tmp_path / "broken.xml").write_text("""<world name="broken" logdir="logs">
  <process name="broken" command="sh -c 'exit 3'">
    <ready timeout="20s"><output>ready</output></ready>
  </process>
</world>
""")
    for name in ("fail1.sh", "fail2.sh", "pass.sh"):
        (tmp_path / name).write_text("#!/bin/sh\nexit %d\n" % (0 if name == "pass.sh" else 1))
        (tmp_path / name).chmod(0o755)
    (tmp_path / "arm.xml").write_text("""<suite name="arm">
  <test type="exec">fail1.sh</test>
  <test type="exec">fail2.sh</test>
  <test type="exec">pass.sh</test>
</suite>""")
    (tmp_path / "base.xml").write_text("""<suite name="base">
  <fixture type="process">broken.xml</fixture>
  <test type="exec">pass.sh</test>
</suite>""")
    r = run_runner("-s", "arm.xml", "-s", "base.xml", cwd=tmp_path)
    assert r.returncode == 1, r
    closing = r.stdout.strip().splitlines()[-1]
    found = re.fullmatch(r"(\d+) passed, (\d+) failed.*", closing)
    assert found, r.stdout
    assert found.group(2) == "3", r.stdout  # two tests and base's fixture
    assert "  failed: 3 (2 tests, 1 fixture)" in r.stdout, r.stdout
