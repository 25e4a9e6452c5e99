# A Python fixture manager: prepares what a suite's tests need and checks it before each test.
#   <fixture type="python" param="--world empty">example_fixture.py</fixture>
import robottestingframework


class FixtureManager:
    def setup(self, param):
        robottestingframework.testReport("starting the world: " + param)
        self.up = True
        return True

    def check(self):
        return self.up  # False: the suite's remaining tests are not run

    def tearDown(self):
        self.up = False
