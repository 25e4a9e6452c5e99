"""An RTF 2.x plug-in, fixture and suite file work unchanged, in both isolation modes."""
import pytest

from conftest import PLUGIN_DIR, run_runner, validate_junit


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_rtf2_plugin_fixture_and_suite_run_unchanged(tmp_path, isolation):
    # The old root spelling, bare plug-in names found through the library path.
    suite = tmp_path / "rtf2.xml"
    suite.write_text("""<?xml version="1.0" encoding="UTF-8"?>
<suit name="rtf2 suite">
    <description>an RTF 2.x suite</description>
    <environment>--robot icubSim</environment>
    <fixture param="--from sim.ini">rtf2_style_fixture</fixture>
    <test type="dll" param="--part left_arm">rtf2_style_test</test>
</suit>
""")
    junit = tmp_path / "r.xml"
    run = run_runner("-v", "--isolation", isolation, "-s", suite, "-o", f"junit:{junit}",
                     env={"LD_LIBRARY_PATH": str(PLUGIN_DIR)})
    assert run.returncode == 0, run
    assert "passed" in run.stdout and "Rtf2StyleTest" in run.stdout, run
    assert "param: --part left_arm" in run.stdout, run
    assert "rtf2 fixture is setting up the world" in run.stdout, run
    assert "suit" in run.stderr, run  # the warning about the old root spelling
    assert run.stdout.rstrip().endswith("1 passed, 0 failed"), run
    validate_junit(junit)
