"""The docs are run (issue 38): every code block of the README's first project and of the
tutorial (docs/tutorial/*.md) is taken from the Markdown and run through the installed tree in
an empty folder, so the pages cannot rot. Each block carries a marker on the line before it:

    <!-- file: PATH -->     the block is written to PATH (relative to the page's folder)
    <!-- run -->            the block is a shell script, run with bash -e in that folder
    <!-- shown: WHY -->     the block is shown, not run (a fragment, a console's output)

A block without a marker fails the test, so a new block is either run or says why not. The
commands find the installed runner on PATH and the CMake package through CMAKE_PREFIX_PATH, as
a user's shell does after `cmake --install build`."""
import os
import re
import subprocess
from pathlib import Path

import pytest

from conftest import RUNNER, SOURCE_DIR, _changes_a_runtime, leftover_processes, marked

MARKER = re.compile(r"^<!--\s*(file:\s*(?P<path>\S+)|(?P<run>run)|shown:[^>]*)\s*-->\s*$")
FENCE = re.compile(r"^(```+|~~~+)(.*)$")


def blocks(text):
    """[(marker line or None, info string, body, line number)] of the fenced blocks of text."""
    found = []
    lines = text.split("\n")
    i = 0
    while i < len(lines):
        fence = FENCE.match(lines[i])
        if not fence:
            i += 1
            continue
        start = i
        previous = next((lines[k] for k in range(i - 1, -1, -1) if lines[k].strip()), "")
        j = i + 1
        while j < len(lines) and not lines[j].startswith(fence.group(1)):
            j += 1
        found.append((MARKER.match(previous.strip()), fence.group(2).strip(),
                      "\n".join(lines[start + 1:j]) + "\n", start + 1))
        i = j + 1
    return found


def first_project(readme):
    """The README's section "A first project in five minutes", up to the next section."""
    match = re.search(r"^## A first project.*?(?=^## )", readme, re.S | re.M)
    assert match, "the README has no section 'A first project'"
    return match.group(0)


def pages():
    readme = SOURCE_DIR / "README.md"
    yield pytest.param(readme, first_project(readme.read_text()), id="README")
    for page in sorted((SOURCE_DIR / "docs" / "tutorial").glob("*.md")):
        yield pytest.param(page, page.read_text(), id=page.stem)


def environment(prefix, mark):
    """The user's shell after installing into prefix: no variable of ours or of a CI engine
    that changes how the runtimes behave (conftest's list), the prefix on PATH."""
    env = {k: v for k, v in os.environ.items()
           if not _changes_a_runtime(k) and not k.startswith(("RTF_", "CMAKE_", "CTEST_"))}
    env["PATH"] = f"{prefix / 'bin'}:{os.environ.get('PATH', '/usr/bin:/bin')}"
    env["CMAKE_PREFIX_PATH"] = str(prefix)
    env.update(marked(mark))
    return env


def test_every_block_is_marked_and_the_pages_have_runnable_blocks():
    for param in pages():
        page, text = param.values
        found = blocks(text)
        unmarked = [line for marker, _, _, line in found if marker is None]
        assert not unmarked, f"{page}: blocks without a marker at lines {unmarked} of the section"
        assert any(m.group("run") for m, _, _, _ in found), f"{page}: no block is run"
    readme_blocks = blocks(first_project((SOURCE_DIR / "README.md").read_text()))
    files = [m.group("path") for m, _, _, _ in readme_blocks if m.group("path")]
    # The first project the issue asks for: a C++ plug-in, a Python test, a suite with a
    # process fixture, its world, and a CMake project.
    assert sorted(files) == sorted(["arm_test.cpp", "checks/robot_answers.py", "world.xml",
                                    "suite.xml", "CMakeLists.txt"]), files
    assert not [1 for m, _, _, _ in readme_blocks if not m.group("path") and not m.group("run")]


@pytest.mark.parametrize("page,text", list(pages()))
def test_the_page_runs_green_through_the_installed_tree(page, text, tmp_path, marker):
    assert RUNNER, "RTF_TESTRUNNER is not set (run through ctest)"
    prefix = Path(RUNNER).resolve().parent.parent
    folder = tmp_path / page.stem
    folder.mkdir()
    env = environment(prefix, marker)
    ran = 0
    for match, info, body, line in blocks(text):
        if match.group("path"):
            target = folder / match.group("path")
            assert folder in target.resolve().parents, f"{page}:{line}: writes outside its folder"
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(body)
        elif match.group("run"):
            assert info in ("sh", "bash", "console"), f"{page}:{line}: a run block is ```sh"
            proc = subprocess.run(["bash", "-e", "-x", "-c", body], cwd=folder, env=env,
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                  errors="replace", timeout=400, start_new_session=True)
            assert proc.returncode == 0, f"{page}:{line}: exit {proc.returncode}\n{proc.stdout}"
            ran += 1
    assert ran
    assert not leftover_processes(marker), "the page's run left processes behind"
