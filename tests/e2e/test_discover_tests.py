"""robottestingframework_discover_tests: a CMake project (discover_project/, copied under the
build tree) built against the installed tree gets one CTest test per test id of its suite,
`ctest -R` runs one of them through the runner, labels come from the tags, a suite changed
after configuring is listed again when ctest starts, and the suites in the source tree find the
plug-in the project built elsewhere in its build tree with no path given."""
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from conftest import BUILD_DIR

PROJECT = Path(__file__).parent / "discover_project"
ANSWER = Path(__file__).parent / "external_project" / "answer_test.cpp"


def run(args, timeout=120, cwd=None):
    return subprocess.run([str(a) for a in args], capture_output=True, text=True,
                          timeout=timeout, cwd=cwd)


def check(args, timeout=300, cwd=None):
    result = run(args, timeout, cwd)
    assert result.returncode == 0, f"{args}\n{result.stdout}\n{result.stderr}"
    return result


@pytest.fixture(scope="module")
def project(tmp_path_factory):
    """(source copy, build folder) of discover_project built against a fresh install."""
    prefix = tmp_path_factory.mktemp("prefix")
    check(["cmake", "--install", BUILD_DIR, "--prefix", prefix])
    source = tmp_path_factory.mktemp("discover") / "source"
    shutil.copytree(PROJECT, source)
    shutil.copy(ANSWER, source / "answer_test.cpp")
    build = source.parent / "build"
    generator = ["-G", "Ninja"] if shutil.which("ninja") else []
    configured = check(["cmake", "-S", source, "-B", build, *generator, "-Wdev",
                        f"-DCMAKE_PREFIX_PATH={prefix}",
                        "-DCMAKE_FIND_PACKAGE_NO_PACKAGE_REGISTRY=ON"], timeout=120)
    assert "CMake Warning" not in configured.stdout + configured.stderr, configured.stderr
    check(["cmake", "--build", build], timeout=300)
    assert (build / "plugins" / "answer_plugin.so").is_file()
    return source, build


def listed(build, *args):
    result = check(["ctest", "--test-dir", build, "-N", *args], timeout=120)
    return re.findall(r"Test +#\d+: (.+)$", result.stdout, re.MULTILINE)


def test_one_ctest_test_per_test_id(project):
    _, build = project
    assert sorted(listed(build)) == ["beside.beside/tests/gripper.sh", "discovered.answers/again",
                                     "discovered.answers/right", "discovered.answers/wrong",
                                     "whole.right"]


def test_a_test_beside_the_suites_folder_has_no_dot_dot_in_its_name(project):
    """suites/beside.xml names ../tests/gripper.sh: its id is beside/tests/gripper.sh (README
    "Test ids"), which ctest runs through the runner's --filter."""
    _, build = project
    beside = run(["ctest", "--test-dir", build, "-V", "-R",
                  r"^beside\.beside/tests/gripper\.sh$"])
    assert beside.returncode == 0, beside.stdout + beside.stderr
    assert re.search(r"^\d+: 1 passed, 0 failed$", beside.stdout, re.MULTILINE), beside.stdout


def test_ctest_runs_one_test_id_through_the_runner(project):
    _, build = project
    right = run(["ctest", "--test-dir", build, "-V", "-R", r"^discovered\.answers/right$"])
    assert right.returncode == 0, right.stdout + right.stderr
    assert "100% tests passed, 0 tests failed out of 1" in right.stdout, right.stdout
    # The runner ran that one test alone.
    assert re.search(r"^\d+: 1 passed, 0 failed$", right.stdout, re.MULTILINE), right.stdout
    wrong = run(["ctest", "--test-dir", build, "-R", r"^discovered\.answers/wrong$",
                 "--output-on-failure"])
    assert wrong.returncode != 0, wrong.stdout
    assert "0% tests passed, 1 tests failed out of 1" in wrong.stdout, wrong.stdout


def test_labels_come_from_the_tags_and_the_call(project):
    _, build = project
    assert listed(build, "-L", "^quick$") == ["discovered.answers/right"]
    assert sorted(listed(build, "-L", "^slow$")) == ["discovered.answers/again",
                                                     "discovered.answers/wrong"]
    assert len(listed(build, "-L", "^answers$")) == 3


def test_the_whole_suite_finds_the_projects_plugin(project):
    _, build = project
    whole = run(["ctest", "--test-dir", build, "-R", r"^whole\.right$", "--output-on-failure"])
    assert whole.returncode == 0, whole.stdout + whole.stderr


def test_a_changed_suite_is_listed_again_when_ctest_starts(project):
    source, build = project
    suite = source / "suites" / "answers.xml"
    text = suite.read_text()
    try:
        suite.write_text(text.replace(
            "</suite>",
            '  <test type="dll" name="more" param="--answer 42">answer_plugin</test>\n</suite>'))
        assert "discovered.answers/more" in listed(build)
        more = run(["ctest", "--test-dir", build, "-R", r"^discovered\.answers/more$"])
        assert more.returncode == 0, more.stdout
    finally:
        suite.write_text(text)
    suite.write_text("<suite name='answers'><test>")  # cannot be read
    try:
        names = listed(build)
        assert "discovered.answers.xml/list" in names, names
        failed = run(["ctest", "--test-dir", build, "-R", r"answers\.xml/list",
                      "--output-on-failure"])
        assert failed.returncode != 0 and "answers.xml" in failed.stdout, failed.stdout
    finally:
        suite.write_text(text)
