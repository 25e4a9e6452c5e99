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


def test_not_found_says_the_plugin_path_and_the_option_that_finds_it(tmp_path):
    """A first project's plug-in is built in its build tree, which nothing searches: the message
    names --plugin-path and RTF_PLUGIN_PATH (what was given, or none) and, since the file is
    below the working folder, the exact option that finds it, which then does."""
    suites = tmp_path / "suites"
    suites.mkdir()
    (suites / "s.xml").write_text(SUITE)
    none = run_runner("--suite", "s.xml", "--no-output", cwd=suites)
    assert none.returncode == 1, none
    assert "in --plugin-path and RTF_PLUGIN_PATH: none given;" in none.stdout, none
    assert "below the working folder" not in none.stdout, none

    (suites / "build" / "lib").mkdir(parents=True)
    shutil.copy(plugin("passing_test"), suites / "build" / "lib" / "libprobe.so")
    hinted = run_runner("--suite", "s.xml", "--no-output", "--plugin-path", "..", cwd=suites,
                        env={"RTF_PLUGIN_PATH": "/nonexistent"})
    assert hinted.returncode == 1, hinted
    assert f"in --plugin-path and RTF_PLUGIN_PATH: {tmp_path}, /nonexistent;" in hinted.stdout, \
        hinted
    assert ("build/lib/libprobe.so is below the working folder: --plugin-path build/lib "
            "(or RTF_PLUGIN_PATH=build/lib) finds it") in hinted.stdout, hinted
    found = run_runner("--suite", "s.xml", "--no-output", "--plugin-path", "build/lib",
                       cwd=suites)
    assert found.returncode == 0 and "1 passed, 0 failed" in found.stdout, found
