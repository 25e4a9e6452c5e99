#include "runner/reports/merge_reports.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace robottestingframework {
namespace runner {

namespace {

using Json = nlohmann::ordered_json;

std::runtime_error problem(const std::string& what) {
    return std::runtime_error("--merge " + what);
}

// The states junit_reporter.cpp writes as an <error> (a timeout is a <failure>).
bool isErrorState(const std::string& state) {
    return state == "error" || state == "crashed" || state == "interrupted";
}

std::string shardName(const ReportedShard& shard) {
    return "shard " + std::to_string(shard.index) + " of " + std::to_string(shard.count);
}

// The shards' reports (and their reruns) are of one run: each says its run's plan
// (planIdentity), and they all say the same. The plan most of them say is the run's (the first
// report's on a tie); a report saying another, or none beside ones that say it, is of another
// run.
void checkOneRun(const std::vector<Report>& reports) {
    std::map<std::string, std::size_t> votes;
    for (const Report& report : reports) {
        if (report.shard.known && !report.shard.plan.empty()) {
            ++votes[report.shard.plan];
        }
    }
    if (votes.empty()) {
        return;  // reports of earlier versions, or of runs that were not sharded
    }
    std::string plan;
    std::size_t most = 0;
    for (const Report& report : reports) {
        const auto found = votes.find(report.shard.plan);
        if (found != votes.end() && found->second > most) {
            plan = found->first;
            most = found->second;
        }
    }
    for (const Report& report : reports) {
        if (report.shard.plan != plan) {
            throw problem(report.path + ": a report of another run (" +
                          (!report.shard.known         ? "it is not a shard's"
                           : report.shard.plan.empty() ? "it says no plan"
                                                       : "its plan is " + report.shard.plan) +
                          "; the shards of " + std::to_string(most) +
                          " other report(s) are of plan " + plan +
                          "): merge the shards of one run, each run with the same suites, "
                          "selection and --shard-count");
        }
    }
}

// Every report of the requested format; with --expect-shards, each shard once and of that count.
// The shards' own reports come first, then the reruns, each in the order given.
std::vector<Report> checkAll(const MergeRequest& request, std::vector<Report> given) {
    std::vector<Report> base;
    std::vector<Report> reruns;
    const ReportFormat format = request.type == "junit" ? ReportFormat::JUnit : ReportFormat::Json;
    for (Report& report : given) {
        const std::string& path = report.path;
        if (report.format != format) {
            throw problem(path + ": a " +
                          std::string(report.format == ReportFormat::JUnit ? "JUnit" : "JSON") +
                          " report; expected " +
                          (format == ReportFormat::JUnit ? "JUnit" : "JSON") +
                          " like the output (" + request.type + ":" + request.file + ")");
        }
    }
    checkOneRun(given);
    for (Report& report : given) {
        (report.shard.rerun ? reruns : base).push_back(std::move(report));
    }
    if (request.expectShards > 0) {
        std::map<unsigned int, std::string> seen;
        for (const auto* group : {&base, &reruns}) {
            for (const Report& report : *group) {
                if (!report.shard.known) {
                    throw problem(report.path +
                                  ": does not say which shard wrote it (expected a report of a "
                                  "run with --shard-index/--shard-count or a CI engine's shard "
                                  "variables)");
                }
                if (report.shard.count != request.expectShards) {
                    throw problem(report.path + ": " + shardName(report.shard) + ", expected " +
                                  std::to_string(request.expectShards) +
                                  " shards (--expect-shards " +
                                  std::to_string(request.expectShards) + ")");
                }
                if (group == &base) {
                    auto found = seen.emplace(report.shard.index, report.path);
                    if (!found.second) {
                        throw problem(found.first->second + " and " + report.path + " are both " +
                                      shardName(report.shard));
                    }
                }
            }
        }
        std::string missing;
        for (unsigned int index = 0; index < request.expectShards; ++index) {
            if (seen.count(index) == 0) {
                missing += (missing.empty() ? "" : ", ") + std::to_string(index);
            }
        }
        if (!missing.empty()) {
            throw problem("--expect-shards " + std::to_string(request.expectShards) +
                          ": no report of shard " + missing);
        }
    }
    for (auto& report : reruns) {
        base.push_back(std::move(report));
    }
    return base;
}

// Which report holds each suite place: a place in two shards' reports is a suite run twice.
class PlaceRegister {
public:
    void add(std::size_t place, const std::string& suite, const std::string& path) {
        auto found = holders_.emplace(place, path);
        if (!found.second) {
            throw problem(found.first->second + " and " + path + " both hold suite '" + suite +
                          "' (place " + std::to_string(place) +
                          "): reports of the shards of one run hold each suite once");
        }
    }

private:
    std::map<std::size_t, std::string> holders_;
};

bool parsePlace(const std::string& text, std::size_t& place) {
    if (text.empty() || text.size() > 12 ||
        text.find_first_not_of("0123456789") != std::string::npos) {
        return false;
    }
    place = static_cast<std::size_t>(std::stoull(text));
    return true;
}

// --- JUnit ---

bool isFixtureCase(const pugi::xml_node test) {
    return isJUnitFixtureCase(test);
}

// The states junit_reporter.cpp names in a suite property ("rtf.state.S.T" = the state).
bool needsStateProperty(const std::string& state) {
    return state == "timed out" || state == "crashed" || state == "interrupted" || state == "flaky";
}

// The merged report is the whole run's: no suite keeps the shard or rerun properties of the
// report it came from, and the state properties are written again from its tests as they are
// after the reruns (an empty <properties> goes). The display names ("rtf.name.S.T") stay: a
// rerun's test replaces the one of its id in place, and a test's id gives its name.
void resetProperties(pugi::xml_node suite) {
    pugi::xml_node properties = suite.child("properties");
    if (!properties) {
        properties = suite.prepend_child("properties");
    }
    for (pugi::xml_node property = properties.first_child(); property;) {
        const pugi::xml_node next = property.next_sibling();
        const std::string name = property.attribute("name").value();
        if (name == shardIndexProperty || name == shardCountProperty || name == shardPlanProperty ||
            name == rerunProperty || name.rfind("rtf.state.", 0) == 0) {
            properties.remove_child(property);
        }
        property = next;
    }
    const std::string place = std::to_string(suite.attribute("id").as_ullong() + 1);
    std::size_t index = 0;
    for (const pugi::xml_node test : suite.children("testcase")) {
        if (isFixtureCase(test)) {
            continue;
        }
        ++index;
        const std::string state = junitTestState(test);
        if (needsStateProperty(state)) {
            pugi::xml_node property = properties.append_child("property");
            property.append_attribute("name") =
                ("rtf.state." + place + "." + std::to_string(index)).c_str();
            property.append_attribute("value") = state.c_str();
        }
    }
    if (!properties.first_child()) {
        suite.remove_child(properties);
    }
}

void setCount(pugi::xml_node node, const char* name, std::size_t value) {
    pugi::xml_attribute attribute = node.attribute(name);
    if (!attribute) {
        attribute = node.append_attribute(name);
    }
    attribute.set_value(std::to_string(value).c_str());
}

std::string seconds(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.3f", value);
    return text;
}

// Replaces in `suite` the n-th test of each name the rerun `again` ran (its last attempt).
void replaceTests(pugi::xml_node suite, const pugi::xml_node again) {
    std::map<std::string, std::size_t> occurrence;
    for (const pugi::xml_node test : again.children("testcase")) {
        if (isFixtureCase(test)) {
            continue;
        }
        const std::string name = test.attribute("name").value();
        std::size_t wanted = occurrence[name]++;
        pugi::xml_node old;
        for (pugi::xml_node candidate : suite.children("testcase")) {
            if (!isFixtureCase(candidate) && name == candidate.attribute("name").value() &&
                wanted-- == 0) {
                old = candidate;
                break;
            }
        }
        if (old) {
            suite.insert_copy_before(test, old);
            suite.remove_child(old);
        } else {
            pugi::xml_node last = suite.last_child();
            while (last && std::string(last.name()) != "testcase" &&
                   std::string(last.name()) != "properties") {
                last = last.previous_sibling();
            }
            if (last) {
                suite.insert_copy_after(test, last);
            } else {
                suite.prepend_copy(test);
            }
        }
    }
}

std::string mergeJUnit(const std::vector<Report>& reports) {
    struct Entry {
        std::size_t place;
        pugi::xml_node node;
    };
    std::vector<Entry> entries;
    PlaceRegister places;
    std::size_t firstRerun = reports.size();
    for (std::size_t r = 0; r < reports.size(); ++r) {
        if (reports[r].shard.rerun) {
            firstRerun = std::min(firstRerun, r);
            continue;
        }
        for (const pugi::xml_node suite :
             reports[r].junit->document_element().children("testsuite")) {
            if (!isJUnitRunSuite(suite)) {
                continue;
            }
            std::size_t place = 0;
            parsePlace(suite.attribute("id").value(), place);  // checked by readReport
            places.add(place, suite.attribute("name").value(), reports[r].path);
            entries.push_back({place, suite});
        }
    }
    std::stable_sort(entries.begin(), entries.end(),
                     [](const Entry& a, const Entry& b) { return a.place < b.place; });

    pugi::xml_document merged;
    pugi::xml_node declaration = merged.append_child(pugi::node_declaration);
    declaration.append_attribute("version") = "1.0";
    declaration.append_attribute("encoding") = "UTF-8";
    pugi::xml_node root = merged.append_child("testsuites");
    root.append_attribute("name") = "RobotTestingFramework";
    for (const Entry& entry : entries) {
        root.append_copy(entry.node);
    }
    for (std::size_t r = firstRerun; r < reports.size(); ++r) {
        for (const pugi::xml_node again :
             reports[r].junit->document_element().children("testsuite")) {
            if (!isJUnitRunSuite(again)) {
                continue;
            }
            pugi::xml_node suite =
                root.find_child_by_attribute("testsuite", "name", again.attribute("name").value());
            if (suite) {
                replaceTests(suite, again);
            } else {
                root.append_copy(again);
            }
        }
    }

    // The counts again, as the runner counts them (junit_reporter.cpp): a failed fixture is a
    // test case in error.
    std::size_t tests = 0;
    std::size_t failures = 0;
    std::size_t errors = 0;
    double time = 0;
    for (pugi::xml_node suite : root.children("testsuite")) {
        resetProperties(suite);
        std::size_t suiteTests = 0;
        std::size_t suiteFailures = 0;
        std::size_t suiteErrors = 0;
        std::size_t suiteSkipped = 0;
        for (const pugi::xml_node test : suite.children("testcase")) {
            ++suiteTests;
            if (isFixtureCase(test)) {
                ++suiteErrors;
                continue;
            }
            const std::string state = junitTestState(test);
            if (state == "skipped") {
                ++suiteSkipped;
            } else if (isErrorState(state)) {
                ++suiteErrors;
            } else if (state == "failed" || state == "timed out") {
                ++suiteFailures;
            }
        }
        setCount(suite, "tests", suiteTests);
        setCount(suite, "failures", suiteFailures);
        setCount(suite, "errors", suiteErrors);
        setCount(suite, "skipped", suiteSkipped);
        tests += suiteTests;
        failures += suiteFailures;
        errors += suiteErrors;
        time += suite.attribute("time").as_double();
    }
    root.append_attribute("tests") = std::to_string(tests).c_str();
    root.append_attribute("failures") = std::to_string(failures).c_str();
    root.append_attribute("errors") = std::to_string(errors).c_str();
    root.append_attribute("time") = seconds(time).c_str();

    std::ostringstream out;
    merged.save(out, "  ", pugi::format_indent, pugi::encoding_utf8);
    return out.str();
}

// --- JSON (CTRF) ---

const char* const failureStates[] = {"failed", "error", "crashed", "timed out", "interrupted"};

// "3.12" -> (3, 12): a test's suite place and its place in the suite, from 1.
bool parseTestId(const std::string& id, std::size_t& suite, std::size_t& test) {
    const std::size_t dot = id.find('.');
    return dot != std::string::npos && parsePlace(id.substr(0, dot), suite) &&
           parsePlace(id.substr(dot + 1), test);
}

std::string suiteOf(const Json& test) {
    return test.contains("suite") ? test["suite"][0].get<std::string>() : std::string();
}

std::string stateOf(const Json& test) {
    return test["extra"][ctrfExtensionKey]["state"].get<std::string>();
}

std::string mergeJson(const std::vector<Report>& reports) {
    struct Entry {
        std::size_t suite;
        std::size_t test;
        Json json;
    };
    std::vector<Entry> entries;
    PlaceRegister places;
    Json fixtures = Json::array();
    Json suites = Json::array();
    long long start = -1;
    long long stop = -1;
    std::string timestamp;
    std::size_t suiteCount = 0;
    std::size_t suitesFailed = 0;
    std::size_t fixturesFailed = 0;
    bool reran = false;
    for (const Report& report : reports) {
        if (report.shard.rerun) {
            reran = true;
            continue;
        }
        const Json& results = report.json["results"];
        std::set<std::size_t> seen;
        for (std::size_t i = 0; i < results["tests"].size(); ++i) {
            const Json& test = results["tests"][i];
            Entry entry{0, 0, test};
            parseTestId(test["testId"].get<std::string>(), entry.suite, entry.test);  // checked
            if (seen.insert(entry.suite).second) {
                places.add(entry.suite, suiteOf(test), report.path);
            }
            entries.push_back(std::move(entry));
        }
        const Json summary = results.value("summary", Json::object());
        const long long reportStart = summary.value("start", -1LL);
        if (reportStart >= 0 && (start < 0 || reportStart < start)) {
            start = reportStart;
            timestamp = report.json.value("timestamp", "");
        }
        stop = std::max(stop, summary.value("stop", -1LL));
        suiteCount += summary.value("suites", 0U);
        suitesFailed += summary.value("/extra/robotology.rtf/suitesFailed"_json_pointer, 0U);
        fixturesFailed += summary.value("/extra/robotology.rtf/fixturesFailed"_json_pointer, 0U);
        const Json extra = results.value("/extra/robotology.rtf"_json_pointer, Json::object());
        for (const auto& fixture : extra.value("fixtureFailures", Json::array())) {
            fixtures.push_back(fixture);
        }
        for (const auto& suite : extra.value("suites", Json::array())) {
            suites.push_back(suite);
        }
    }
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
        return a.suite != b.suite ? a.suite < b.suite : a.test < b.test;
    });
    std::stable_sort(suites.begin(), suites.end(), [](const Json& a, const Json& b) {
        return a["place"].get<std::size_t>() < b["place"].get<std::size_t>();
    });
    // A failed fixture names its suite only: ordered by that suite's place.
    auto placeOf = [&suites](const Json& fixture) {
        for (const auto& suite : suites) {
            if (suite["name"] == fixture.value("suite", "")) {
                return suite["place"].get<std::size_t>();
            }
        }
        return std::size_t(-1);
    };
    std::stable_sort(fixtures.begin(), fixtures.end(),
                     [&](const Json& a, const Json& b) { return placeOf(a) < placeOf(b); });
    // A rerun replaces the n-th test of each suite and name it ran again; the place stays.
    for (const Report& report : reports) {
        if (!report.shard.rerun) {
            continue;
        }
        std::map<std::pair<std::string, std::string>, std::size_t> occurrence;
        for (const Json& test : report.json["results"]["tests"]) {
            const auto key = std::make_pair(suiteOf(test), test["name"].get<std::string>());
            std::size_t wanted = occurrence[key]++;
            auto old = std::find_if(entries.begin(), entries.end(), [&](const Entry& entry) {
                return suiteOf(entry.json) == key.first &&
                       entry.json["name"].get<std::string>() == key.second && wanted-- == 0;
            });
            if (old != entries.end()) {
                const Json id = old->json["testId"];
                old->json = test;
                old->json["testId"] = id;
            } else {
                entries.push_back({0, 0, test});
            }
        }
    }

    Json tests = Json::array();
    std::map<std::string, std::size_t> counts;
    std::set<std::size_t> failedSuites;
    for (const Entry& entry : entries) {
        tests.push_back(entry.json);
        ++counts[entry.json["status"].get<std::string>()];
        const std::string state = stateOf(entry.json);
        ++counts["state:" + state];
        if (std::find(std::begin(failureStates), std::end(failureStates), state) !=
            std::end(failureStates)) {
            failedSuites.insert(entry.suite);
        }
    }
    if (reran) {
        // The reruns may have turned failed suites into passed ones: counted again from the
        // tests (and the failed fixtures, whose tests were only skipped).
        suitesFailed = failedSuites.size() + fixtures.size();
    }

    Json summary = Json::object();
    summary["tests"] = tests.size();
    summary["passed"] = counts["passed"];
    summary["failed"] = counts["failed"];
    summary["skipped"] = counts["skipped"];
    summary["pending"] = counts["pending"];
    summary["other"] = counts["other"];
    summary["suites"] = suiteCount;
    summary["start"] = std::max(start, 0LL);
    summary["stop"] = std::max(stop, std::max(start, 0LL));
    summary["duration"] = summary["stop"].get<long long>() - summary["start"].get<long long>();
    Json rtf = Json::object();
    for (const char* state : failureStates) {
        rtf[state] = counts[std::string("state:") + state];
    }
    rtf["flaky"] = counts["state:flaky"];
    rtf["suitesFailed"] = suitesFailed;
    rtf["fixturesFailed"] = fixturesFailed;  // each suite, and so each fixture, in one shard
    summary["extra"] = {{ctrfExtensionKey, rtf}};

    Json merged = Json::object();
    merged["reportFormat"] = "CTRF";
    merged["specVersion"] =
        reports.empty() ? std::string("0.0.0") : reports[0].json.value("specVersion", "0.0.0");
    merged["timestamp"] =
        timestamp.empty() && !reports.empty() ? reports[0].json.value("timestamp", "") : timestamp;
    merged["generatedBy"] = "robottestingframework-testrunner";
    merged["results"] = {
        {"tool", {{"name", "robottestingframework-testrunner"}}},
        {"summary", summary},
        {"tests", tests},
        {"extra", {{ctrfExtensionKey, {{"fixtureFailures", fixtures}, {"suites", suites}}}}}};
    return merged.dump(-1, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace

std::string mergeReports(const MergeRequest& request) {
    std::vector<Report> reports;
    for (const auto& path : request.reports) {
        reports.push_back(readReport("--merge", path));
    }
    return mergeReports(request, std::move(reports));
}

std::string mergeReports(const MergeRequest& request, std::vector<Report> reports) {
    reports = checkAll(request, std::move(reports));
    return request.type == "junit" ? mergeJUnit(reports) : mergeJson(reports);
}

}  // namespace runner
}  // namespace robottestingframework
