#include <exception>
#include <memory>
#include <stdexcept>

#include <robottestingframework/Arguments.h>
#include <robottestingframework/FixtureEvents.h>
#include <robottestingframework/Test.h>
#include <robottestingframework/TestResult.h>

#include "core/guarded_call.h"
#include "isolation/event_writer.h"
#include "isolation/worker.h"
#include "languages/test_loader.h"
#include "platform/file_descriptor.h"

namespace robottestingframework {
namespace isolation {

namespace {

// Stands for the suite in the worker: fixture reports are about it.
class FixtureOwner : public Test {
public:
    explicit FixtureOwner(const std::string& name) : Test(name) {}
    void run(TestResult& /*result*/) override {}
    bool succeeded() const override { return true; }
};

// A collapse, from whatever thread the fixture reports it, becomes a record.
class CollapseSender : public FixtureEvents {
public:
    explicit CollapseSender(EventWriter& writer) : writer_(writer) {}
    void fixtureCollapsed(TestMessage reason) override {
        WireRecord record;
        record.kind = WireKind::FixtureCollapsed;
        record.message = reason;
        writer_.send(record);
    }
    // Sent before tearDown's reply: the runner's side hands it to its suite.
    bool fixtureCheckFailed(const std::string& name, const TestMessage& failure,
                            const Attachment* attachment) override {
        WireRecord record;
        record.kind = WireKind::FixtureCheckFailed;
        record.name = name;
        record.message = failure;
        if (attachment != nullptr) {
            record.attachment = std::make_shared<const Attachment>(*attachment);
        }
        writer_.send(record);
        return true;
    }

private:
    EventWriter& writer_;
};

std::string exceptionText() {
    try {
        throw;
    } catch (const std::exception& e) {
        return exceptionReason(e);  // whole, past a NUL in what it quotes
    } catch (...) {
        return "unhandled exception of unknown type";
    }
}

void reply(EventWriter& writer, bool ok, const TestMessage& why = TestMessage()) {
    WireRecord record;
    record.kind = WireKind::Reply;
    record.flag = ok;
    record.message = why;
    writer.send(record);
}

}  // namespace

int runFixtureWorker(const WorkRequest& request, int channel) {
    EventWriter writer(channel);
    std::string error;
    std::unique_ptr<languages::LoadedFixture> loaded;
    try {
        loaded = languages::loadFixture(request.type, request.path, error);
    } catch (...) {
        error = exceptionText();
    }
    FixtureManager* fixture = loaded ? loaded->get() : nullptr;

    FixtureOwner owner(request.name);
    CollapseSender collapse(writer);
    TestResult result;
    result.addListener(&writer);
    if (fixture != nullptr) {
        fixture->setParam(request.param);
        if (!request.name.empty()) {
            fixture->setName(request.name);
        }
        fixture->setDispatcher(&collapse);
        fixture->setResult(&result, &owner);
    }

    WireDecoder decoder;
    std::string bytes;
    for (;;) {
        WireRecord call;
        WireDecoder::Status status = decoder.next(call);
        if (status == WireDecoder::Status::Corrupt) {
            return 3;
        }
        if (status == WireDecoder::Status::NeedMore) {
            bytes.clear();
            if (platform::readSome(channel, bytes) <= 0) {
                break;  // the runner closed the channel: we are done
            }
            decoder.feed(bytes);
            continue;
        }
        if (call.kind != WireKind::Call) {
            continue;
        }
        if (fixture == nullptr) {
            reply(writer, false, TestMessage("cannot load fixture " + request.path, error));
            continue;
        }
        try {
            if (call.name == "setup") {
                // The argv the suite built, each word ended by a '\0'.
                std::vector<std::string> words;
                const std::string joined = call.message.getMessage();
                for (std::size_t start = 0; start < joined.size();) {
                    std::size_t end = joined.find('\0', start);
                    if (end == std::string::npos) {
                        end = joined.size();
                    }
                    words.push_back(joined.substr(start, end - start));
                    start = end + 1;
                }
                std::vector<char*> argv;
                for (std::string& word : words) {
                    argv.push_back(&word[0]);
                }
                argv.push_back(nullptr);
                bool ok = fixture->setup(static_cast<int>(words.size()), argv.data());
                reply(writer, ok);
            } else if (call.name == "check") {
                reply(writer, fixture->check());
            } else if (call.name == "tearDown") {
                fixture->tearDown();
                reply(writer, true);
            } else {
                reply(writer, false, TestMessage("unknown call " + call.name));
            }
        } catch (...) {
            // The runner's suite says which fixture and which call; this is the reason.
            reply(writer, false, TestMessage(exceptionText()));
        }
    }
    loaded.reset();
    return 0;
}

}  // namespace isolation
}  // namespace robottestingframework
