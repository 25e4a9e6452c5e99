# A Ruby test case: the runner loads this file and runs class TestCase.
#   robottestingframework-testrunner --test example_test.rb -p "--camera none" -v
class TestCase
  def setup(param)
    RobotTestingFramework::setName("ruby example")
    RobotTestingFramework::testReport("param: #{param}")
    true # false stops here
  end

  def run
    RobotTestingFramework::testReport("environment: #{RobotTestingFramework::getEnvironment}")
    RobotTestingFramework::testCheck([1, 2, 3].sum == 6, "sums an array")
  end

  def tearDown
    RobotTestingFramework::testReport("done")
  end
end
