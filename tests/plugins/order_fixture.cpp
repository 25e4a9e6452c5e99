// A fixture that appends "setup NAME", "check NAME", "teardown NAME" to the file given with
// "--log FILE"; "--fail-setup" makes its set-up fail (after a report), "--throw-teardown" makes
// its tear-down throw.
#include <cstdio>
#include <stdexcept>
#include <string>

#include <robottestingframework/Arguments.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

using robottestingframework::Arguments;

class OrderFixture : public robottestingframework::FixtureManager {
public:
    bool setup(int argc, char** argv) override {
        Arguments::getOption(argc, argv, "--log", log_);
        Arguments::getOption(argc, argv, "--name", name_);
        note("setup");
        throwInTearDown_ = Arguments::hasOption(argc, argv, "--throw-teardown");
        if (Arguments::hasOption(argc, argv, "--fail-setup")) {
            ROBOTTESTINGFRAMEWORK_FIXTURE_REPORT("fixture " + name_ + " refuses to start");
            return false;
        }
        return true;
    }
    bool check() override {
        note("check");
        return true;
    }
    void tearDown() override {
        note("teardown");
        if (throwInTearDown_) {
            throw std::runtime_error("the arm is stuck");
        }
    }

private:
    void note(const std::string& what) {
        if (std::FILE* file = std::fopen(log_.c_str(), "a")) {
            std::fprintf(file, "%s %s\n", what.c_str(), name_.c_str());
            std::fclose(file);
        }
    }

    std::string log_;
    std::string name_;
    bool throwInTearDown_ = false;
};

ROBOTTESTINGFRAMEWORK_PREPARE_FIXTURE_PLUGIN(OrderFixture)
