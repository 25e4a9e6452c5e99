"""Where the runner looks for a plug-in named without a folder: beside the suite file, then each
--plugin-path DIR in order, then RTF_PLUGIN_PATH's folders, then the system's library path. Two
plug-ins with one file name, one passing and one failing, in different folders show which was
taken. Run from the suite's own folder with relative paths."""
import os
import shutil

from conftest import plugin, run_runner

SUITE = '<suite name="probes"><test type="dll">probe</test></suite>\n'


def layout(tmp_path):
    suites = tmp_path / "suites"
    suites.mkdir()
    (suites / "s.xml").write_text(SUITE)
    for folder, source in (("passing", "passing_test"), ("failing", "failing_test")):
        (tmp_path / folder).mkdir()
        shutil.copy(plugin(source), tmp_path / folder / "probe.so")
    return suites


def test_a_plugin_path_folder_is_searched(tmp_path):
    suites = layout(tmp_path)
    missing = run_runner("--suite", "s.xml", "--no-output", cwd=suites)
    assert missing.returncode == 1, missing  # a plug-in not found is a failed test
    assert "cannot load probe" in missing.stdout, missing
    found = run_runner("--suite", "s.xml", "--no-output", "--plugin-path", "../passing",
                       cwd=suites)
    assert found.returncode == 0, found
    assert "1 passed, 0 failed" in found.stdout, found


def test_the_environment_variable_is_searched_after_the_option(tmp_path):
    suites = layout(tmp_path)
    env_only = run_runner("--suite", "s.xml", "--no-output", cwd=suites,
                          env={"RTF_PLUGIN_PATH": "/nonexistent:../failing"})
    assert env_only.returncode == 1, env_only
    assert "two and two make five" in env_only.stdout, env_only  # found, ran and failed
    both = run_runner("--suite", "s.xml", "--no-output", "--plugin-path", "../passing",
                      cwd=suites, env={"RTF_PLUGIN_PATH": "../failing"})
    assert both.returncode == 0, both
    # In order: the first --plugin-path that has it wins.
    two = run_runner("--suite", "s.xml", "--no-output", "--plugin-path", "../failing",
                     "--plugin-path", "../passing", cwd=suites)
    assert two.returncode == 1 and "two and two make five" in two.stdout, two


def test_the_suites_folder_comes_first(tmp_path):
    suites = layout(tmp_path)
    shutil.copy(plugin("failing_test"), suites / "probe.so")
    beside = run_runner("--suite", "s.xml", "--no-output", "--plugin-path", "../passing",
                        cwd=suites)
    assert beside.returncode == 1 and "two and two make five" in beside.stdout, beside


def test_a_plugin_path_that_is_no_folder_is_an_error(tmp_path):
    suites = layout(tmp_path)
    bad = run_runner("--suite", "s.xml", "--no-output", "--plugin-path", "../nowhere",
                     cwd=suites)
    assert bad.returncode == 2, bad
    assert "--plugin-path ../nowhere: no such folder" in bad.stderr, bad
    assert not os.path.exists(tmp_path / "nowhere")
