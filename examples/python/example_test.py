# A Python test case: the runner loads this file and runs class TestCase.
#   robottestingframework-testrunner --test example_test.py -p "--joints 6" -v
import robottestingframework


class TestCase:
    def setup(self, param):
        robottestingframework.setName("python example")
        robottestingframework.testReport("param: " + param)
        self.joints = 6
        return True  # False stops here: run() and tearDown() are not called

    def run(self):
        robottestingframework.testReport("param again: " + robottestingframework.getParam())
        robottestingframework.testReport("environment: " + robottestingframework.getEnvironment())
        robottestingframework.testCheck(self.joints == 6, "the arm has six joints")
        robottestingframework.testFailIf(self.joints >= 0, "a negative joint count")

    def tearDown(self):
        robottestingframework.testReport("done")
