# A Python test case registered with robottestingframework_add_script_test.
import robottestingframework


class TestCase:
    def setup(self, param):
        robottestingframework.setName("python_ok")
        return True

    def run(self):
        robottestingframework.testReport("checking from Python")
        robottestingframework.testCheck(1 + 1 == 2, "one and one make two")
