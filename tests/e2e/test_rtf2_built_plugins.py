"""A C++ plug-in built against RTF 2.0.1 (Debian's binary packages, unpacked into the build tree
by scripts/rtf2-binaries.sh: the CTest fixture e2e.rtf2_binaries), run by this runner on a
machine where RTF 2.x's library is still installed (apt keeps it for the user's old plug-ins):
it is refused before it is loaded, with a message that says why and how to rebuild it, in both
isolation modes, as a test and as a fixture, and through RTF 2.x's loader classes used from a
program. Loaded, RTF 2.x's library clashed with this one: `crashed: SIGABRT`."""
import glob
import subprocess
from pathlib import Path

import pytest

from conftest import BUILD_DIR, LIBDIR, RUNNER, run_runner

RTF2 = BUILD_DIR / "rtf2-binary" / "root"

OLD_TEST = """
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;

class OldTest : public TestCase {
public:
    OldTest() : TestCase("OldTest") {}
    void run() override { ROBOTTESTINGFRAMEWORK_TEST_CHECK(2 < 3, "2 is smaller than 3"); }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(OldTest)
"""

OLD_FIXTURE = """
#include <robottestingframework/FixtureManager.h>
#include <robottestingframework/dll/Plugin.h>

using namespace robottestingframework;

class OldFixture : public FixtureManager {
public:
    bool setup(int, char**) override { return true; }
    void tearDown() override {}
};

ROBOTTESTINGFRAMEWORK_PREPARE_FIXTURE_PLUGIN(OldFixture)
"""

# A program of the user's own that loads a plug-in with RTF 2.x's loader class, built against
# this version (its RTF 2.x library names: -lrobottestingframework -lrobottestingframework-dll).
LOADER_PROGRAM = """
#include <cstdio>
#include <robottestingframework/dll/DllPluginLoader.h>

int main(int argc, char* argv[]) {
    robottestingframework::plugin::DllPluginLoader loader;
    if (argc < 2 || loader.open(argv[1]) == nullptr) {
        std::printf("refused: %s\\n", loader.getLastError().c_str());
        return 1;
    }
    std::printf("loaded\\n");
    return 0;
}
"""


def rtf2_folders():
    """RTF 2.0.1's include and library folders (Debian's multiarch ones)."""
    include = glob.glob(str(RTF2 / "usr/include/*/robottestingframework/TestCase.h"))
    libs = glob.glob(str(RTF2 / "usr/lib/*/librobottestingframework.so.2"))
    assert include and libs, f"RTF 2.0.1's packages are not unpacked in {RTF2}"
    return str(Path(include[0]).parent.parent), str(Path(libs[0]).parent)


def build_against_rtf2(folder, name, source):
    """lib<name>.so in `folder`, built as an RTF 2.0.1 user built it: -lrobottestingframework."""
    include, lib = rtf2_folders()
    (folder / f"{name}.cpp").write_text(source)
    subprocess.run(["g++", "-shared", "-fPIC", "-o", f"lib{name}.so", f"{name}.cpp",
                    f"-I{include}", f"-L{lib}", "-lrobottestingframework",
                    "-lrobottestingframework-dll"], cwd=folder, check=True, timeout=120)
    needed = subprocess.run(["objdump", "-p", f"lib{name}.so"], cwd=folder, check=True,
                            capture_output=True, text=True).stdout
    assert "librobottestingframework.so.2" in needed, needed


def rtf2_still_installed():
    """The environment of a machine with RTF 2.x's library still installed beside ours."""
    return {"LD_LIBRARY_PATH": rtf2_folders()[1]}


def assert_told(output):
    assert "was built against RTF 2.x" in output, output
    assert "librobottestingframework.so.2" in output, output
    assert "compile unchanged" in output and "rebuild it" in output, output
    assert "SIGABRT" not in output and "crashed" not in output, output


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_a_test_plugin_built_against_rtf2_is_refused_with_how_to_rebuild(tmp_path, isolation):
    build_against_rtf2(tmp_path, "old_test", OLD_TEST)
    r = run_runner("--isolation", isolation, "-t", "libold_test.so", "-o", "junit:r.xml",
                   cwd=tmp_path, env=rtf2_still_installed())
    assert r.returncode == 1, r
    assert_told(r.output)
    assert r.stdout.rstrip().endswith("0 passed, 1 failed"), r
    junit = (tmp_path / "r.xml").read_text()
    assert "was built against RTF 2.x" in junit and "<failure" in junit, junit


@pytest.mark.parametrize("isolation", ["process", "none"])
def test_a_fixture_plugin_built_against_rtf2_is_refused_with_how_to_rebuild(tmp_path, isolation):
    build_against_rtf2(tmp_path, "old_fixture", OLD_FIXTURE)
    (tmp_path / "suite.xml").write_text("""<suite name="old">
  <fixture>old_fixture</fixture>
  <test type="exec">/bin/true</test>
</suite>
""")
    r = run_runner("--isolation", isolation, "-s", "suite.xml", cwd=tmp_path,
                   env=rtf2_still_installed())
    assert r.returncode == 1, r
    assert_told(r.output)


def test_rtf2_loader_classes_refuse_a_plugin_built_against_rtf2(tmp_path):
    build_against_rtf2(tmp_path, "old_test", OLD_TEST)
    prefix = Path(RUNNER).parent.parent
    (tmp_path / "loader.cpp").write_text(LOADER_PROGRAM)
    subprocess.run(["g++", "-std=c++17", "-o", "loader", "loader.cpp",
                    f"-I{prefix / 'include'}", f"-L{prefix / LIBDIR}",
                    f"-Wl,-rpath,{prefix / LIBDIR}", "-lrobottestingframework",
                    "-lrobottestingframework-dll"], cwd=tmp_path, check=True, timeout=120)
    r = subprocess.run(["./loader", "./libold_test.so"], cwd=tmp_path, capture_output=True,
                       text=True, timeout=60, env={"PATH": "/usr/bin:/bin",
                                                   **rtf2_still_installed()})
    assert r.returncode == 1, r
    assert_told(r.stdout + r.stderr)
