"""The command line's three descriptions, all made from the runner's option table
(src/runner/cli/option_table.cpp): --help, the installed man page and the checked-in
reference docs/reference/command-line.md name the same options; the reference is the one the
table makes today."""
import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from conftest import RUNNER, SOURCE_DIR, cache_value, run_runner

REFERENCE = SOURCE_DIR / "docs" / "reference" / "command-line.md"
REGENERATE = ("regenerate it from the build tree's runner: build/bin/robottestingframework-testrunner "
              "--help-markdown > docs/reference/command-line.md")


def installed_man_page():
    prefix = Path(RUNNER).parent.parent
    # GNUInstallDirs caches an empty MANDIR, meaning share/man.
    mandir = cache_value("CMAKE_INSTALL_MANDIR", "") or "share/man"
    return prefix / mandir / "man1" / \
        "robottestingframework-testrunner.1"


def names_in_help(text):
    """Every option name of --help: the words of `  -t,--test FILE   ...` lines."""
    names = set()
    for line in text.splitlines():
        match = re.match(r"  ((?:--?[\w?][\w-]*,)*--?[\w?][\w-]*)(?: |$)", line)
        if match:
            names.update(match.group(1).split(","))
    return names


def names_in_roff(text):
    """Every option name of the man page's OPTIONS: the bold words of each .TP's tag line."""
    names = set()
    lines = text.splitlines()
    for i, line in enumerate(lines[:-1]):
        if line == ".TP":
            for bold in re.findall(r"\\fB(.*?)\\fR", lines[i + 1]):
                names.add(bold.replace("\\-", "-"))
    return names


def names_in_reference(text):
    """Every option name of the reference's tables: the `-x` or `--name VALUE` code spans of
    each row's first cell."""
    names = set()
    for line in text.splitlines():
        if line.startswith("| `"):
            first_cell = line.split(" | ")[0]
            for code in re.findall(r"`([^`]*)`", first_cell):
                names.add(code.split(" ")[0])
    return names


def test_the_reference_is_what_the_option_table_makes(tmp_path):
    run = run_runner("--help-markdown", cwd=tmp_path)
    assert run.returncode == 0, run
    assert REFERENCE.is_file(), f"{REFERENCE} is missing: {REGENERATE}"
    assert run.stdout == REFERENCE.read_text(), \
        f"{REFERENCE} differs from what the option table makes: {REGENERATE}"


def test_help_the_man_page_and_the_reference_name_the_same_options(tmp_path):
    help_run = run_runner("--help", cwd=tmp_path)
    assert help_run.returncode == 0, help_run
    in_help = names_in_help(help_run.stdout)
    # RTF 2.x's names, ours, and the help flag's -? are all there.
    assert {"-t", "--test", "-s", "--suite", "-?", "-h", "--help", "--version", "-j",
            "--jobs", "--world-up", "--history-report"} <= in_help, in_help
    page = installed_man_page()
    assert page.is_file(), f"the man page is not installed at {page}"
    in_man = names_in_roff(page.read_text())
    in_reference = names_in_reference(REFERENCE.read_text())
    assert in_man == in_help, (in_man ^ in_help)
    assert in_reference == in_help, (in_reference ^ in_help)
    # The hidden flags that make the pages are in none of them.
    assert not {"--help-man", "--help-markdown"} & (in_help | in_man | in_reference)


@pytest.mark.skipif(shutil.which("man") is None, reason="man is not installed")
def test_man_renders_the_installed_page(tmp_path):
    env = dict(os.environ, LC_ALL="C", MANWIDTH="200", MANPAGER="cat", PAGER="cat")
    rendered = subprocess.run(["man", "-l", str(installed_man_page())], capture_output=True,
                              text=True, env=env, timeout=60, cwd=tmp_path)
    assert rendered.returncode == 0, rendered.stderr
    assert "robottestingframework-testrunner - Runs Robot Testing Framework" in rendered.stdout
    for words in ("-t, --test FILE", "-h, -?, --help", "--history-report [N]", "EXIT STATUS",
                  "--isolation MODE"):
        assert words in rendered.stdout, (words, rendered.stdout)
    assert "warning" not in rendered.stderr, rendered.stderr
