"""The CMake package's script-language components, as RTF 2.x named them: for each language
this build made, `find_package(RobotTestingFramework COMPONENTS LUA|PYTHON|RUBY)` succeeds,
RobotTestingFramework_<LANG>_FOUND is TRUE and RobotTestingFramework_LIBRARIES lists
RobotTestingFramework::RTF_<lang>. (The library targets RTF_lua, RTF_python and RTF_ruby come
with the script loaders' public API.)"""
import subprocess

import pytest

from conftest import BUILD_DIR
from test_package import BUILT_MODULES

LANGUAGES = {"LUA": "lua", "PYTHON": "python", "RUBY": "ruby"}
BUILT = [upper for upper, lower in LANGUAGES.items()
         if f"robottestingframework-{lower}.so" in BUILT_MODULES]


def configure(tmp_path, components):
    source = tmp_path / "src"
    source.mkdir()
    (source / "CMakeLists.txt").write_text(f"""cmake_minimum_required(VERSION 3.16)
project(languages LANGUAGES CXX)
find_package(RobotTestingFramework REQUIRED COMPONENTS DLL {" ".join(components)})
foreach(component DLL LUA PYTHON RUBY)
    file(APPEND ${{CMAKE_BINARY_DIR}}/found.txt
         "${{component}}=${{RobotTestingFramework_${{component}}_FOUND}}\\n")
endforeach()
file(APPEND ${{CMAKE_BINARY_DIR}}/found.txt "LIBRARIES=${{RobotTestingFramework_LIBRARIES}}\\n")
""")
    build = tmp_path / "build"
    result = subprocess.run(["cmake", "-S", str(source), "-B", str(build),
                             f"-DRobotTestingFramework_DIR={BUILD_DIR}"],
                            capture_output=True, text=True, timeout=120)
    return result, build


def test_every_built_language_is_found(tmp_path):
    assert BUILT, "this build made no script language module"
    result, build = configure(tmp_path, BUILT)
    assert result.returncode == 0, result.stdout + result.stderr
    values = dict(line.split("=", 1) for line in (build / "found.txt").read_text().splitlines())
    assert values["DLL"] == "TRUE", values
    libraries = values["LIBRARIES"].split(";")
    for upper in BUILT:
        assert values[upper] == "TRUE", values
        assert f"RobotTestingFramework::RTF_{LANGUAGES[upper]}" in libraries, values


@pytest.mark.parametrize("component", ["FORTRAN"])
def test_unknown_component_is_not_found(tmp_path, component):
    result, _ = configure(tmp_path, [component])
    assert result.returncode != 0, result.stdout
    assert component in result.stdout + result.stderr, result.stderr
