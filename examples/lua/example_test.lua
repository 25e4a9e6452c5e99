-- A Lua test case: the file fills the global table TestCase.
--   robottestingframework-testrunner --test example_test.lua -p "--hand left" -v
TestCase = {}

function TestCase.setup(param)
    robottestingframework.setName("lua example")
    robottestingframework.testReport("param: " .. param)
    return true -- false stops here
end

function TestCase.run()
    robottestingframework.testReport("environment: " .. robottestingframework.getEnvironment())
    robottestingframework.testCheck(2 + 2 == 4, "arithmetic still works")
    robottestingframework.testFailIf(#robottestingframework.getParam() <= 100, "a very long param")
end

function TestCase.tearDown()
    robottestingframework.testReport("done")
end
