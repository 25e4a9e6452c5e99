"""The CI engine files of examples/ci (docs/how-to/ci-engines.md) work: they parse, and their commands,
run as each engine would run them (4 shards as 4 processes, each with its engine's variables),
give merged reports equal to the one-machine run."""
import ast
import os
import shlex
import subprocess

import yaml

from conftest import BUILD_DIR, RUNNER, SOURCE_DIR, validate_ctrf, validate_junit
from shard_cases import engine_env, make_suites, normal_ctrf, normal_junit

CI = SOURCE_DIR / "examples" / "ci"


def sh(command, cwd, **variables):
    """Runs `command` as the engine would (sh -c), the runner on the PATH."""
    env = engine_env(**variables)
    env["PATH"] = os.path.dirname(RUNNER) + os.pathsep + env["PATH"]
    result = subprocess.run(["sh", "-c", command], cwd=cwd, env=env, capture_output=True,
                            text=True, timeout=120, stdin=subprocess.DEVNULL)
    return result


def one_machine(tmp_path, suites):
    result = sh(f"robottestingframework-testrunner --suites {suites} -o junit:one.xml "
                "-o json:one.json", tmp_path)
    assert result.returncode == 1, result
    return tmp_path / "one.xml", tmp_path / "one.json"


def assert_same_as_one_machine(junit, ctrf, one):
    validate_junit(junit)
    assert normal_junit(junit) == normal_junit(one[0])
    if ctrf is not None:
        validate_ctrf(ctrf)
        assert normal_ctrf(ctrf) == normal_ctrf(one[1])


def test_gitlab_parallel_4_and_its_merge_job(tmp_path):
    pipeline = yaml.safe_load((CI / "gitlab-ci.yml").read_text())
    shards, merge = pipeline["robot-tests"], pipeline["merge-reports"]
    assert shards["parallel"] == 4
    assert merge["needs"][0]["job"] == "robot-tests"
    make_suites(tmp_path / "suites")
    one = one_machine(tmp_path, "suites")
    for node in range(1, 5):  # GitLab counts from 1
        for command in shards["script"]:
            result = sh(command, tmp_path, CI_NODE_INDEX=node, CI_NODE_TOTAL=4)
            assert result.returncode in (0, 1), result
            assert f"shard {node - 1} of 4 (from GitLab CI" in result.stdout, result
    for command in merge["script"]:
        result = sh(command, tmp_path, CI_NODE_TOTAL=1)
        assert result.returncode == 0, result
    assert merge["artifacts"]["reports"]["junit"] == "report.xml"
    assert_same_as_one_machine(tmp_path / "report.xml", tmp_path / "report.json", one)


def test_kubernetes_indexed_job_and_its_merge_step(tmp_path):
    shards, merge = list(yaml.safe_load_all((CI / "k8s-indexed-job.yaml").read_text()))
    assert shards["spec"]["completionMode"] == "Indexed"
    count = shards["spec"]["completions"]
    assert count == 4
    container = shards["spec"]["template"]["spec"]["containers"][0]
    env = {item["name"]: item["value"] for item in container["env"]}
    assert env == {"RTF_SHARD_COUNT": str(count)}
    work = tmp_path / container["workingDir"].lstrip("/")
    make_suites(work / "suites")
    (work / "reports").mkdir()
    one = one_machine(work, "suites")
    assert container["command"][:2] == ["sh", "-c"]
    for index in range(count):
        result = sh(container["command"][2], work, JOB_COMPLETION_INDEX=index, **env)
        assert result.returncode in (0, 1), result
        assert f"shard {index} of 4 (from Kubernetes Indexed Job" in result.stdout, result
    merger = merge["spec"]["template"]["spec"]["containers"][0]
    assert merger["command"][:2] == ["sh", "-c"]
    result = sh(merger["command"][2], tmp_path / merger["workingDir"].lstrip("/"))
    assert result.returncode == 0, result
    assert_same_as_one_machine(work / "reports" / "report.xml", work / "reports" / "report.json",
                               one)


def test_bazel_sh_test_with_shard_count(tmp_path):
    build = ast.parse((CI / "bazel" / "BUILD").read_text())
    calls = [node.value for node in build.body
             if isinstance(node, ast.Expr) and isinstance(node.value, ast.Call)]
    assert [call.func.id for call in calls] == ["sh_test"]
    rule = {kw.arg: ast.literal_eval(kw.value) for kw in calls[0].keywords if kw.arg != "data"}
    assert rule["shard_count"] == 4
    wrapper = CI / "bazel" / rule["srcs"][0]
    assert os.access(wrapper, os.X_OK)
    package = tmp_path / "runfiles"
    make_suites(package / rule["args"][0])
    one = one_machine(package, rule["args"][0])
    logs = []
    for index in range(rule["shard_count"]):
        # What Bazel gives each shard (its test encyclopedia): the shard, a file to touch, where
        # the JUnit report goes, a scratch folder.
        log = tmp_path / "testlogs" / f"shard_{index + 1}_of_4"
        scratch = log / "tmp"
        scratch.mkdir(parents=True)
        status = log / "status"
        result = sh(shlex.join([str(wrapper), *rule["args"]]), package, TEST_SHARD_INDEX=index,
                    TEST_TOTAL_SHARDS=4, TEST_SHARD_STATUS_FILE=status,
                    XML_OUTPUT_FILE=log / "test.xml", TEST_TMPDIR=scratch)
        assert result.returncode in (0, 1), result
        assert f"shard {index} of 4 (from Bazel" in result.stdout, result
        assert status.exists(), "TEST_SHARD_STATUS_FILE was not touched"
        assert not list(package.glob("result.*")), "--no-output wrote a result file"
        logs.append(log / "test.xml")
    result = sh("robottestingframework-testrunner --merge junit:report.xml --expect-shards 4 "
                "testlogs/shard_*_of_4/test.xml", tmp_path)
    assert result.returncode == 0, result
    assert_same_as_one_machine(tmp_path / "report.xml", None, one)


def test_googletest_variables_shard_too(tmp_path):
    make_suites(tmp_path / "suites")
    one = one_machine(tmp_path, "suites")
    for index in range(2):
        result = sh(f"robottestingframework-testrunner --suites suites -o junit:g{index}.xml "
                    f"-o json:g{index}.json", tmp_path, GTEST_SHARD_INDEX=index,
                    GTEST_TOTAL_SHARDS=2)
        assert result.returncode in (0, 1), result
        assert f"shard {index} of 2 (from GoogleTest" in result.stdout, result
    for kind in ("junit", "json"):
        ext = "xml" if kind == "junit" else "json"
        result = sh(f"robottestingframework-testrunner --merge {kind}:merged.{ext} "
                    f"--expect-shards 2 g0.{ext} g1.{ext}", tmp_path)
        assert result.returncode == 0, result
    assert_same_as_one_machine(tmp_path / "merged.xml", tmp_path / "merged.json", one)


def test_the_docs_name_the_example_files():
    docs = (SOURCE_DIR / "docs" / "how-to" / "ci-engines.md").read_text()
    for name in ("examples/ci/gitlab-ci.yml", "examples/ci/k8s-indexed-job.yaml",
                 "examples/ci/bazel/BUILD", "examples/ci/bazel/rtf_shard.sh"):
        assert name in docs
        assert (SOURCE_DIR / name).exists()
    assert BUILD_DIR.exists()
