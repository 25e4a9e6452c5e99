// The DDS world's test (tests/e2e/dds/dds.xml): subscribes to the world's topic
// "rtf_world_samples" and, over a window of samples,
//   - measures their rate (Hz) and their mean latency (ms, send to take, on CLOCK_MONOTONIC)
//     against the limits its param gives;
//   - checks that every sample carries this process's world token (the identity of its network
//     namespace, as the publisher reads it) and that they all come from one writer: a sample
//     of another world fails the test, naming its token.
// Param (all optional but --config, which takes the rest of the line):
//   --seconds S         the window (default 1)
//   --rate MIN MAX      the rate's limits in Hz (default 50 200)
//   --latency MAX       the mean latency's upper limit in ms (default 50)
//   --match-timeout S   how long to wait for the world's writer (default 10)
//   --domain N          the DDS domain (default 0)
//   --config TEXT       Cyclone DDS's configuration, as CYCLONEDDS_URI takes it (XML or
//                       file://...); without it, CYCLONEDDS_URI or Cyclone's defaults
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <set>
#include <sstream>
#include <string>

#include <dds/dds.h>
#include <robottestingframework/TestAssert.h>
#include <robottestingframework/dll/Plugin.h>

#include "world_sample.h"

namespace {

std::int64_t monotonicNs() {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);
    return static_cast<std::int64_t>(now.tv_sec) * 1000000000LL + now.tv_nsec;
}

std::string networkToken() {
    char token[256];
    ssize_t length = readlink("/proc/self/ns/net", token, sizeof token - 1);
    return length < 0 ? std::string("(unreadable)") : std::string(token, length);
}

struct Settings {
    double seconds = 1;
    double minRate = 50, maxRate = 200;
    double maxLatencyMs = 50;
    double matchTimeout = 10;
    dds_domainid_t domain = 0;
    std::string config;
    std::string error;
};

Settings parse(const std::string& param) {
    Settings settings;
    std::istringstream words(param);
    std::string word;
    while (words >> word) {
        if (word == "--seconds") {
            words >> settings.seconds;
        } else if (word == "--rate") {
            words >> settings.minRate >> settings.maxRate;
        } else if (word == "--latency") {
            words >> settings.maxLatencyMs;
        } else if (word == "--match-timeout") {
            words >> settings.matchTimeout;
        } else if (word == "--domain") {
            words >> settings.domain;
        } else if (word == "--config") {
            std::getline(words >> std::ws, settings.config);
            break;
        } else {
            settings.error = "unknown word in the param: " + word;
            return settings;
        }
        if (!words) {
            settings.error = "a number was expected after " + word;
            return settings;
        }
    }
    return settings;
}

// Deletes a DDS entity (and what it contains) at the end of a scope.
struct Entity {
    dds_entity_t handle;
    ~Entity() {
        if (handle > 0)
            dds_delete(handle);
    }
};

}  // namespace

class DdsWorldTest : public robottestingframework::TestCase {
public:
    DdsWorldTest() : TestCase("DdsWorldTest") {}

    void run() override {
        const Settings settings = parse(getParam());
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(settings.error.empty(), settings.error);
        const std::string token = networkToken();
        ROBOTTESTINGFRAMEWORK_TEST_REPORT("this world's token: " + token);

        Entity domain{0};
        if (!settings.config.empty()) {
            domain.handle = dds_create_domain(settings.domain, settings.config.c_str());
            ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(
                domain.handle > 0,
                std::string("dds_create_domain: ") + dds_strretcode(domain.handle));
        }
        Entity participant{dds_create_participant(settings.domain, nullptr, nullptr)};
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(
            participant.handle > 0,
            std::string("dds_create_participant: ") + dds_strretcode(participant.handle));
        dds_entity_t topic = dds_create_topic(participant.handle, &rtf_dds_WorldSample_desc,
                                              "rtf_world_samples", nullptr, nullptr);
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(
            topic > 0, std::string("dds_create_topic: ") + dds_strretcode(topic));
        dds_qos_t* qos = dds_create_qos();
        dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
        dds_qset_history(qos, DDS_HISTORY_KEEP_ALL, 0);
        dds_entity_t reader = dds_create_reader(participant.handle, topic, qos, nullptr);
        dds_delete_qos(qos);
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(
            reader > 0, std::string("dds_create_reader: ") + dds_strretcode(reader));

        // The world's writer, found by discovery.
        const std::int64_t matchDeadline =
            monotonicNs() + static_cast<std::int64_t>(settings.matchTimeout * 1e9);
        dds_subscription_matched_status_t matched{};
        while (dds_get_subscription_matched_status(reader, &matched) == DDS_RETCODE_OK &&
               matched.current_count == 0 && monotonicNs() < matchDeadline) {
            dds_sleepfor(DDS_MSECS(1));
        }
        ROBOTTESTINGFRAMEWORK_ASSERT_ERROR_IF_FALSE(
            matched.current_count > 0,
            "no writer of rtf_world_samples within " + std::to_string(settings.matchTimeout) +
                " s: is the world's publisher running, with a configuration that reaches "
                "this test?");

        // The window: every sample taken as it arrives (a waitset wakes on data).
        dds_set_status_mask(reader, DDS_DATA_AVAILABLE_STATUS);
        Entity waitset{dds_create_waitset(participant.handle)};
        dds_waitset_attach(waitset.handle, reader, reader);
        std::set<dds_instance_handle_t> writers;
        std::set<std::string> foreignTokens;
        std::size_t samples = 0, foreign = 0;
        double latencySumMs = 0, latencyMaxMs = 0;
        const std::int64_t start = monotonicNs();
        const std::int64_t end = start + static_cast<std::int64_t>(settings.seconds * 1e9);
        void* buffers[64] = {};
        dds_sample_info_t infos[64];
        for (std::int64_t now = start; now < end; now = monotonicNs()) {
            dds_waitset_wait(waitset.handle, nullptr, 0, end - now);
            const dds_return_t taken = dds_take(reader, buffers, infos, 64, 64);
            const std::int64_t arrival = monotonicNs();
            for (dds_return_t i = 0; i < taken; ++i) {
                if (!infos[i].valid_data)
                    continue;
                const auto* sample = static_cast<const rtf_dds_WorldSample*>(buffers[i]);
                ++samples;
                const double latencyMs = (arrival - sample->sent_ns) / 1e6;
                latencySumMs += latencyMs;
                latencyMaxMs = std::max(latencyMaxMs, latencyMs);
                writers.insert(infos[i].publication_handle);
                if (token != sample->token) {
                    ++foreign;
                    foreignTokens.insert(std::string(sample->token) + " (pid " +
                                         std::to_string(sample->pid) + ")");
                }
            }
            if (taken > 0)
                dds_return_loan(reader, buffers, taken);
        }
        const double elapsed = (monotonicNs() - start) / 1e9;

        ROBOTTESTINGFRAMEWORK_TEST_MEASURE("samples", static_cast<double>(samples), "");
        ROBOTTESTINGFRAMEWORK_TEST_MEASURE_IN("rate", samples / elapsed, "Hz", settings.minRate,
                                              settings.maxRate);
        if (samples > 0) {
            ROBOTTESTINGFRAMEWORK_TEST_MEASURE_IN("latency", latencySumMs / samples, "ms", 0,
                                                  settings.maxLatencyMs);
            ROBOTTESTINGFRAMEWORK_TEST_MEASURE("latency max", latencyMaxMs, "ms");
        }
        std::string others;
        for (const auto& other : foreignTokens)
            others += (others.empty() ? "" : ", ") + other;
        ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_FALSE(samples > 0, "no sample within the window");
        ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_FALSE(
            foreign == 0, std::to_string(foreign) + " of " + std::to_string(samples) +
                              " samples come from another world: " + others +
                              "; this world's token is " + token);
        ROBOTTESTINGFRAMEWORK_TEST_FAIL_IF_FALSE(
            writers.size() <= 1, "the samples come from " + std::to_string(writers.size()) +
                                     " writers; this world has one");
    }
};

ROBOTTESTINGFRAMEWORK_PREPARE_PLUGIN(DdsWorldTest)
