#include "runner/suites/suite_file.h"

#include <robottestingframework/dll/DllPluginLoader.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <sstream>
#include <unordered_map>

#include <pugixml.hpp>

#include "platform/bounded_file.h"
#include "runner/model/test_id.h"
#include "runner/model/value_limits.h"
#include "runner/suites/parametrize.h"

namespace robottestingframework {
namespace runner {

namespace {

const char* const testTypes[] = {"dll", "python", "lua", "ruby", "exec"};
const char* const fixtureTypes[] = {"dll", "python", "process"};

std::string trim(const std::string& text) {
    const char* space = " \t\r\n";
    std::size_t first = text.find_first_not_of(space);
    if (first == std::string::npos) {
        return {};
    }
    std::size_t last = text.find_last_not_of(space);
    return text.substr(first, last - first + 1);
}

std::string folderOf(const std::string& path) {
    std::size_t slash = path.rfind('/');
    if (slash == std::string::npos) {
        return ".";
    }
    return slash == 0 ? "/" : path.substr(0, slash);
}

std::string stemOf(const std::string& path) {
    std::size_t slash = path.rfind('/');
    std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
    std::size_t dot = name.rfind('.');
    return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> items;
    // No stream: this runs twice per test, and a stringstream costs more than the rest of it.
    std::size_t begin = 0;
    while (begin < text.size()) {
        std::size_t end = text.find(',', begin);
        if (end == std::string::npos) {
            end = text.size();
        }
        std::string item = trim(text.substr(begin, end - begin));
        if (!item.empty()) {
            items.push_back(std::move(item));
        }
        begin = end + 1;
    }
    return items;
}

// One word for a param, as a shell would quote it.
std::string quoted(const std::string& word) {
    std::string text = "'";
    for (char c : word) {
        text += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return text + "'";
}

template <std::size_t N>
std::string listOf(const char* const (&names)[N]) {
    std::string text;
    for (std::size_t i = 0; i < N; ++i) {
        text += (i == 0 ? "" : i + 1 == N ? " or " : ", ") + std::string(names[i]);
    }
    return text;
}

template <std::size_t N>
bool isOneOf(const std::string& value, const char* const (&names)[N]) {
    return std::any_of(std::begin(names), std::end(names),
                       [&value](const char* name) { return value == name; });
}

// A regular file of at most maxSuiteFileBytes; `what` names it in messages ("suite file").
std::string readBoundedFile(const std::string& path, const std::string& what) {
    std::string content;
    std::string error;
    if (!platform::readBoundedFile(path, what, maxSuiteFileBytes, platform::Pipes::Refused, content,
                                   error)) {
        throw SuiteFileError(error);
    }
    return content;
}

// Reads one suite document; every error names the file and the line of the offending element.
class SuiteReader {
public:
    SuiteReader(const std::string& text, const std::string& path,
                std::vector<std::string>& warnings, variables::VariableTable& table)
        : text_(text), path_(path), folder_(folderOf(path)), warnings_(warnings), table_(table) {
        // memchr, not a loop over each byte: a suite of 10 000 tests is 750 kB of text.
        const char* begin = text_.data();
        const char* end = begin + text_.size();
        for (const char* at = begin;
             (at = static_cast<const char*>(std::memchr(at, '\n', end - at))) != nullptr; ++at) {
            newlines_.push_back(static_cast<std::size_t>(at - begin));
        }
    }

private:
    unsigned int lineAt(std::ptrdiff_t offset) const {
        if (offset < 0) {
            offset = 0;
        }
        auto before =
            std::lower_bound(newlines_.begin(), newlines_.end(), static_cast<std::size_t>(offset));
        return static_cast<unsigned int>(before - newlines_.begin()) + 1;
    }

    SourceLocation where(pugi::xml_node node) const {
        return SourceLocation{path_, lineAt(node.offset_debug())};
    }

    [[noreturn]] void fail(std::ptrdiff_t offset, const std::string& what) const {
        throw SuiteFileError(path_ + ":" + std::to_string(lineAt(offset)) + ": " + what);
    }
    [[noreturn]] void fail(pugi::xml_node node, const std::string& what) const {
        fail(node.offset_debug(), what);
    }

    void checkAttributes(pugi::xml_node node, std::initializer_list<const char*> allowed) const {
        for (pugi::xml_attribute attribute : node.attributes()) {
            bool known = std::any_of(allowed.begin(), allowed.end(), [&](const char* name) {
                return std::strcmp(name, attribute.name()) == 0;
            });
            if (!known) {
                std::string expected;
                for (const char* name : allowed) {
                    expected += (expected.empty() ? "" : ", ") + std::string(name);
                }
                fail(node,
                     "unknown attribute '" + std::string(attribute.name()) + "' on <" +
                         node.name() + ">" +
                         (expected.empty() ? " (it takes none)" : " (expected " + expected + ")"));
            }
        }
    }

    // The element's text, trimmed; it may hold nothing but text.
    std::string textOf(pugi::xml_node node) const {
        std::string text;
        for (pugi::xml_node child : node.children()) {
            if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) {
                text += child.value();
            } else if (child.type() == pugi::node_element) {
                fail(child, "<" + std::string(child.name()) + "> inside <" + node.name() + ">; <" +
                                node.name() + "> holds only text");
            }
        }
        return trim(text);
    }

    std::string pluginOf(pugi::xml_node node) const {
        std::string plugin = textOf(node);
        if (plugin.empty()) {
            fail(node, "<" + std::string(node.name()) +
                           "> without a plug-in; write its file name as the element's text, "
                           "e.g. <" +
                           node.name() + ">libmytest.so</" + node.name() + ">");
        }
        return plugin;
    }

    // pluginOf for the <test> elements of a suite, which mostly name the plug-in of the test
    // before them: the same text is not gathered and trimmed again.
    const std::string& testPluginOf(pugi::xml_node node) {
        pugi::xml_node only = node.first_child();
        const bool plain = only && only.type() == pugi::node_pcdata && !only.next_sibling();
        if (plain && haveLastPlugin_ && lastPluginText_ == only.value()) {
            return lastPlugin_;
        }
        haveLastPlugin_ = false;
        lastPlugin_ = pluginOf(node);
        if (plain) {
            lastPluginText_ = only.value();
            haveLastPlugin_ = true;
        }
        return lastPlugin_;
    }

    unsigned int repetitionOf(pugi::xml_node node, const std::string& text) const {
        unsigned int runs = 0;
        const std::string problem = checkRepetition(text, runs);
        if (!problem.empty()) {
            fail(node, "repetition=\"" + text + "\" " + problem + " (e.g. repetition=\"3\")");
        }
        return runs;
    }

    double secondsOf(pugi::xml_node node, const std::string& text, const std::string& what) const {
        double seconds = 0;
        const std::string problem = checkSeconds(text, seconds);
        if (!problem.empty()) {
            fail(node, what + " \"" + text + "\" " + problem);
        }
        return seconds;
    }

    template <std::size_t N>
    std::string typeOf(pugi::xml_node node, const char* const (&types)[N]) const {
        pugi::xml_attribute attribute = node.attribute("type");
        if (!attribute) {
            return {};
        }
        std::string type = trim(attribute.value());
        if (!isOneOf(type, types)) {
            fail(node, "unknown " + std::string(node.name()) + " type '" + type + "' (expected " +
                           listOf(types) + ")");
        }
        return type;
    }

    // Suites often list one plug-in many times: look each name up once, and give every test
    // naming it the same two strings.
    const std::pair<SharedString, SharedString>& pluginAndPath(const std::string& plugin) const {
        if (lastResolved_ != nullptr && lastResolved_->first == plugin) {
            return lastResolved_->second;
        }
        auto known = resolved_.find(plugin);
        if (known == resolved_.end()) {
            known = resolved_
                        .emplace(plugin,
                                 std::make_pair(SharedString(plugin),
                                                SharedString(plugin::findPlugin(plugin, folder_))))
                        .first;
        }
        lastResolved_ = &*known;
        return known->second;
    }

public:
    SuiteSpec readSuite(pugi::xml_node root) {
        std::string rootName = root.name();
        if (rootName == "suit") {
            warnings_.push_back(where(root).toString() +
                                ": warning: the root element <suit> is the old spelling of "
                                "<suite>; it is read the same way");
        } else if (rootName != "suite") {
            fail(root, "the root element is <" + rootName + ">; expected <suite name=\"...\">");
        }
        checkAttributes(root, {"name", "tags", "exclusive", "network"});

        SuiteSpec suite;
        suite.where = where(root);
        if (root.attribute("exclusive")) {
            const std::string exclusive = trim(root.attribute("exclusive").value());
            if (exclusive != "true" && exclusive != "false") {
                fail(root, "exclusive=\"" + exclusive + "\": expected true or false");
            }
            suite.exclusive = exclusive == "true";
        }
        if (root.attribute("network")) {
            const std::string network = trim(root.attribute("network").value());
            if (network != "private" && network != "host") {
                fail(root, "network=\"" + network +
                               "\": expected private (a network of its own) or host (the "
                               "machine's)");
            }
            suite.network =
                network == "private" ? SuiteSpec::Network::Private : SuiteSpec::Network::Host;
        }
        suite.name = trim(root.attribute("name").value());
        if (suite.name.empty()) {
            suite.name = stemOf(path_);
        }
        bool haveDescription = false;
        bool haveEnvironment = false;
        bool haveTimeout = false;
        auto once = [this](pugi::xml_node node, bool& seen) {
            if (seen) {
                fail(node, "<" + std::string(node.name()) + "> given twice; a suite has one");
            }
            seen = true;
        };

        // Variables first: they may be used anywhere in the suite, before or after them.
        std::vector<pugi::xml_node> declared;
        for (pugi::xml_node node = root.child("variable"); node;
             node = node.next_sibling("variable")) {
            defineVariable(node, variables::Source::Suite, declared);
        }
        checkVariables(declared);
        suite.tags = splitList(expand(root, root.attribute("tags").value()));

        // One allocation of the right size: growing (or shrinking) a vector of 10 000 specs
        // holds two copies at once, the largest moment of a big run.
        std::size_t tests = 0;
        for (pugi::xml_node node = root.child("test"); node; node = node.next_sibling("test")) {
            ++tests;
        }
        suite.tests.reserve(tests);
        for (pugi::xml_node node : root.children()) {
            if (node.type() == pugi::node_pcdata || node.type() == pugi::node_cdata) {
                fail(node, "text \"" + trim(node.value()) +
                               "\" directly inside <suite>; put plug-ins in <test> elements");
            }
            if (node.type() != pugi::node_element) {
                continue;
            }
            std::string name = node.name();
            if (name == "description") {
                once(node, haveDescription);
                checkAttributes(node, {});
                suite.description = textOf(node);
            } else if (name == "environment") {
                once(node, haveEnvironment);
                checkAttributes(node, {});
                suite.environment = expand(node, textOf(node));
            } else if (name == "timeout") {
                once(node, haveTimeout);
                checkAttributes(node, {});
                suite.timeout = secondsOf(node, expand(node, textOf(node)), "<timeout>");
            } else if (name == "variable") {
                continue;  // read above
            } else if (name == "fixture") {
                suite.fixtures.push_back(readFixture(node));
            } else if (name == "resource") {
                suite.resources.push_back(readResource(node));
                checkPoolOnce(suite.resources);
            } else if (name == "test") {
                const std::size_t first = suite.tests.size();
                if (node.child("parametrize")) {
                    readParametrized(node, suite.tests);
                } else {
                    suite.tests.push_back(node.attribute("file")
                                              ? readTestFile(node)
                                              : readTest(node, expand(node, testPluginOf(node))));
                }
                for (std::size_t i = first; i < suite.tests.size(); ++i) {
                    TestSpec& added = suite.tests[i];
                    for (const auto& tag : suite.tags) {
                        if (std::find(added.tags.begin(), added.tags.end(), tag) ==
                            added.tags.end()) {
                            added.tags.push_back(tag);
                        }
                    }
                }
            } else {
                fail(node, "unknown element <" + name +
                               "> (expected description, environment, timeout, variable, "
                               "fixture, resource or test)");
            }
        }
        checkResourceUses(suite);
        giveResourcesToWorlds(suite);
        for (const auto& variable : table_.all()) {
            suite.variables.push_back(
                {variable.first, valueOf(root, variable.first), variable.second.origin});
        }
        suite.variablesUsed = table_.used();
        for (const auto& name : usedInTestFiles_) {
            if (std::find(suite.variablesUsed.begin(), suite.variablesUsed.end(), name) ==
                suite.variablesUsed.end()) {
                suite.variablesUsed.push_back(name);
            }
        }
        assignTestIds(suite, folder_);
        return suite;
    }

    // A test file: one <test> as in a suite, with <variable> defaults of its own; the
    // attributes of the suite's <test file="..."> (`overrides`) win over the file's.
    TestSpec readTestDocument(pugi::xml_node root, pugi::xml_node overrides) {
        if (std::string(root.name()) != "test") {
            fail(root, "the root element is <" + std::string(root.name()) +
                           ">; a test file holds one <test> written as in a suite");
        }
        checkAttributes(root, {"type", "param", "environment", "repetition", "name", "timeout",
                               "depends", "tags"});
        std::vector<pugi::xml_node> declared;
        std::string plugin;
        for (pugi::xml_node child : root.children()) {
            if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) {
                plugin += child.value();
            } else if (child.type() == pugi::node_element &&
                       std::string(child.name()) == "variable") {
                defineVariable(child, variables::Source::TestFile, declared);
            } else if (child.type() == pugi::node_element) {
                fail(child, "<" + std::string(child.name()) +
                                "> inside <test>; a test file's <test> holds its plug-in as "
                                "text and <variable> defaults");
            }
        }
        checkVariables(declared);
        plugin = trim(plugin);
        if (plugin.empty()) {
            fail(root, "<test> without a plug-in; write its file name as the element's text");
        }
        return readTest(root, expand(root, plugin), overrides);
    }

    const variables::VariableTable& table() const { return table_; }

private:
    void defineVariable(pugi::xml_node node, variables::Source source,
                        std::vector<pugi::xml_node>& declared) {
        checkAttributes(node, {"name"});
        const std::string name = trim(node.attribute("name").value());
        if (!variables::isVariableName(name)) {
            fail(node, "<variable name=\"" + name +
                           "\">: a name is letters, digits, _, - and ., not starting with a "
                           "digit (e.g. <variable name=\"robot\">icubSim</variable>)");
        }
        for (const pugi::xml_node& other : declared) {
            if (name == trim(other.attribute("name").value())) {
                fail(node, "<variable name=\"" + name + "\"> given twice (first at line " +
                               std::to_string(where(other).line) + ")");
            }
        }
        declared.push_back(node);
        table_.define({name, textOf(node), source, where(node).toString()});
    }

    // Each variable is expanded once at its own line: a wrong one is reported there.
    void checkVariables(const std::vector<pugi::xml_node>& declared) {
        for (const pugi::xml_node& node : declared) {
            valueOf(node, trim(node.attribute("name").value()));
        }
    }

    std::string valueOf(pugi::xml_node node, const std::string& name) {
        return guarded(node, [&] { return table_.valueOf(name); });
    }

    // ${...} in `text` of `node`; an error names this file and the node's line.
    std::string expand(pugi::xml_node node, const std::string& text) {
        return guarded(node, [&] { return table_.expand(text); });
    }

    template <typename Expansion>
    std::string guarded(pugi::xml_node node, Expansion expansion) {
        try {
            return expansion();
        } catch (const variables::ExpandError& e) {
            std::string message = e.message;
            if (e.kind == variables::ExpandError::Kind::Undefined) {
                message += " (define it with <variable name=\"" + e.name +
                           "\">VALUE</variable> in the suite, or pass --var " + e.name + "=VALUE";
                std::string defined;
                for (const auto& variable : table_.all()) {
                    defined += (defined.empty() ? "" : ", ") + variable.first;
                }
                message +=
                    defined.empty() ? "; no variable is defined)" : "; defined: " + defined + ")";
            }
            fail(node, message);
        }
    }

    // <resource lock="robot:left-arm"/> or <resource pool="ros_domain" count="1"
    // default="ID ..."/>.
    ResourceSpec readResource(pugi::xml_node node) {
        checkAttributes(node, {"lock", "pool", "count", "default"});
        if (!textOf(node).empty()) {
            fail(node,
                 "<resource> holds no text; write <resource lock=\"NAME\"/> or "
                 "<resource pool=\"NAME\" count=\"1\"/>");
        }
        ResourceSpec resource;
        resource.where = where(node);
        const bool lock = static_cast<bool>(node.attribute("lock"));
        const bool pool = static_cast<bool>(node.attribute("pool"));
        if (lock == pool) {
            fail(node, "<resource> takes one of lock=\"NAME\" or pool=\"NAME\"");
        }
        if (lock) {
            if (node.attribute("count") || node.attribute("default")) {
                fail(node,
                     "<resource lock=...> takes no count nor default: a lock has one "
                     "holder");
            }
            resource.lock = expand(node, node.attribute("lock").value());
            if (resource.lock.empty()) {
                fail(node, "<resource lock=\"\">: a lock needs a name (e.g. robot:left-arm)");
            }
            for (char c : resource.lock) {
                if (std::isspace(static_cast<unsigned char>(c)) ||
                    static_cast<unsigned char>(c) < 0x20) {
                    fail(node, "<resource lock=\"" + resource.lock +
                                   "\">: a lock name has no spaces (e.g. robot:left-arm)");
                }
            }
            return resource;
        }
        resource.pool = trim(expand(node, node.attribute("pool").value()));
        bool name =
            !resource.pool.empty() && !std::isdigit(static_cast<unsigned char>(resource.pool[0]));
        for (char c : resource.pool) {
            name = name && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
        }
        if (!name) {
            fail(node, "<resource pool=\"" + resource.pool +
                           "\">: a pool name is letters, digits and _, not starting with a "
                           "digit (as in the --resources file)");
        }
        if (node.attribute("count")) {
            const std::string text = trim(expand(node, node.attribute("count").value()));
            const bool digits =
                !text.empty() && text.size() <= 4 &&
                std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
            const unsigned long count = digits ? std::stoul(text) : 0;
            if (count < 1 || count > 1000) {
                fail(node, "count=\"" + text + "\": expected a whole number from 1 to 1000");
            }
            resource.count = static_cast<unsigned int>(count);
        }
        if (node.attribute("default")) {
            std::istringstream words(expand(node, node.attribute("default").value()));
            for (std::string id; words >> id;) {
                if (!isPoolItemId(id)) {
                    fail(node, "default=\"...\": item \"" + id +
                                   "\" is not an id (letters, digits, _, - and .)");
                }
                if (std::find(resource.defaults.begin(), resource.defaults.end(), id) !=
                    resource.defaults.end()) {
                    fail(node, "default=\"...\": item \"" + id +
                                   "\" is given twice (each item of a pool once: two suites "
                                   "would hold it at once)");
                }
                resource.defaults.push_back(id);
            }
            if (resource.defaults.empty()) {
                fail(node, "default=\"\": give the pool's items, e.g. default=\"18831 18841\"");
            }
        }
        return resource;
    }

    // A pool named twice in one suite could never be served (its items are taken all at once,
    // each <resource> checked alone): one <resource> with count="N" says it.
    void checkPoolOnce(const std::vector<ResourceSpec>& resources) const {
        const ResourceSpec& added = resources.back();
        for (std::size_t i = 0; !added.pool.empty() && i + 1 < resources.size(); ++i) {
            const ResourceSpec& earlier = resources[i];
            if (earlier.pool == added.pool) {
                throw SuiteFileError(added.where.toString() + ": pool \"" + added.pool +
                                     "\" is taken a second time (first at line " +
                                     std::to_string(earlier.where.line) +
                                     "); write one <resource pool=\"" + added.pool + "\" count=\"" +
                                     std::to_string(earlier.count + added.count) + "\"/> for " +
                                     std::to_string(earlier.count + added.count) + " items");
            }
        }
    }

    // ${resource.NAME} gets an item of the pool NAME: the suite must take one.
    void checkResourceUses(const SuiteSpec& suite) const {
        auto check = [&](const std::string& text, const SourceLocation& at) {
            for (const auto& pool : variables::resourcesUsed(text)) {
                const bool taken = std::any_of(
                    suite.resources.begin(), suite.resources.end(),
                    [&pool](const ResourceSpec& resource) { return resource.pool == pool; });
                if (!taken) {
                    throw SuiteFileError(at.toString() + ": ${resource." + pool +
                                         "} but the suite takes no item of pool " + pool +
                                         " (add <resource pool=\"" + pool + "\"/>)");
                }
            }
        };
        for (const auto& test : suite.tests) {
            check(test.param, test.where);
            check(test.environment, test.where);
        }
        for (const auto& fixture : suite.fixtures) {
            check(fixture.param, fixture.where);
        }
    }

    // A process fixture's world file may use ${resource.POOL} of each pool the suite takes:
    // the items reach it as --var resource.POOL=ITEMS (the scheduler fills the marker in).
    static void giveResourcesToWorlds(SuiteSpec& suite) {
        std::string words;
        for (const auto& resource : suite.resources) {
            if (!resource.pool.empty()) {
                words += " --var " + quoted("resource." + resource.pool + "=" +
                                            variables::resourceMarker(resource.pool));
            }
        }
        for (auto& fixture : suite.fixtures) {
            // A shared world is the run's, not the suite's: no suite's items reach it.
            if (fixture.type == "process" && fixture.scope == FixtureSpec::Scope::Suite &&
                !words.empty()) {
                fixture.param += fixture.param.empty() ? words.substr(1) : words;
            }
        }
    }

    FixtureSpec readFixture(pugi::xml_node node) {
        checkAttributes(node, {"param", "type", "scope"});
        FixtureSpec fixture;
        fixture.where = where(node);
        fixture.plugin = expand(node, pluginOf(node));
        fixture.type = typeOf(node, fixtureTypes);
        fixture.param = expand(node, node.attribute("param").value());
        if (const pugi::xml_attribute scope = node.attribute("scope")) {
            const std::string value = trim(scope.value());
            if (value == "run") {
                fixture.scope = FixtureSpec::Scope::Run;
            } else if (value != "suite") {
                fail(node, "<fixture scope=\"" + value +
                               "\">: expected \"suite\" (the default: the suite's own) or "
                               "\"run\" (one world shared by the suites of the run)");
            }
        }
        if (fixture.scope == FixtureSpec::Scope::Run) {
            if (fixture.type != "process") {
                fail(node,
                     "<fixture scope=\"run\"> is for type=\"process\" fixtures (world "
                     "files) only; this one is of type \"" +
                         fixture.type + "\"");
            }
            if (!variables::resourcesUsed(fixture.param).empty() ||
                !variables::resourcesUsed(fixture.plugin.str()).empty()) {
                fail(node,
                     "<fixture scope=\"run\"> with ${resource.NAME}: a shared world is "
                     "the run's, not one suite's, and gets no suite's pool items");
            }
        }
        if (fixture.type == "process") {
            // Every variable reaches the world file: the suite's under the fixture's own
            // --var, the command line's over it.
            std::string before;
            std::string after;
            for (const auto& variable : table_.all()) {
                const std::string word =
                    "--var " +
                    quoted(variable.first + "=" + variables::escape(valueOf(node, variable.first)));
                std::string& side =
                    variable.second.source >= variables::Source::VarFile ? after : before;
                side += (side.empty() ? "" : " ") + word;
            }
            for (const std::string* part : {&fixture.param, &after}) {
                if (!part->empty()) {
                    before += (before.empty() ? "" : " ") + *part;
                }
            }
            fixture.param = before;
        }
        const auto& named = pluginAndPath(fixture.plugin);
        fixture.plugin = named.first;
        fixture.path = named.second;
        return fixture;
    }

    // The attributes of a <test> besides its type, each the first of its name.
    struct TestAttributes {
        pugi::xml_attribute param, environment, repetition, name, timeout, depends, tags;

        // Finds them in one pass over `node`'s attributes (a suite of 10 000 tests looked each
        // name up in each); false when it has one it does not know (a test file's `file`).
        bool read(pugi::xml_node node) {
            bool known = true;
            for (pugi::xml_attribute attribute : node.attributes()) {
                pugi::xml_attribute* slot = slotOf(attribute.name());
                if (slot == nullptr) {
                    known = known && std::strcmp(attribute.name(), "type") == 0;
                } else if (!*slot) {
                    *slot = attribute;
                }
            }
            return known;
        }
        // Those of `over` where it has them.
        void overlay(const TestAttributes& over) {
            for (pugi::xml_attribute TestAttributes::*field : fields) {
                if (over.*field) {
                    this->*field = over.*field;
                }
            }
        }

    private:
        static constexpr pugi::xml_attribute TestAttributes::*fields[] = {
            &TestAttributes::param, &TestAttributes::environment, &TestAttributes::repetition,
            &TestAttributes::name,  &TestAttributes::timeout,     &TestAttributes::depends,
            &TestAttributes::tags};
        pugi::xml_attribute* slotOf(const char* attribute) {
            static constexpr const char* names[] = {"param",   "environment", "repetition", "name",
                                                    "timeout", "depends",     "tags"};
            for (std::size_t i = 0; i < std::size(names); ++i) {
                if (std::strcmp(attribute, names[i]) == 0) {
                    return &(this->*fields[i]);
                }
            }
            return nullptr;
        }
    };

    TestSpec readTest(pugi::xml_node node, const std::string& plugin,
                      pugi::xml_node overrides = pugi::xml_node()) {
        TestAttributes given;
        const bool known = given.read(node);
        if (!overrides && !known) {
            checkAttributes(node, {"type", "param", "environment", "repetition", "name", "timeout",
                                   "depends", "tags"});  // says which, and what is expected
        }
        if (overrides) {
            TestAttributes over;
            over.read(overrides);
            given.overlay(over);
        }
        // Most attributes are not given: nothing to expand (a suite of 10 000 tests read each
        // of them through the variable table).
        auto value = [&](pugi::xml_attribute attribute) {
            if (!attribute) {
                return std::string();
            }
            return expand(node, instance_ == nullptr
                                    ? std::string(attribute.value())
                                    : substituteAxes(attribute.value(), *instance_));
        };
        TestSpec test;
        test.where = where(node);
        const auto& named = pluginAndPath(plugin);
        test.plugin = named.first;
        test.path = named.second;
        pugi::xml_node typed = overrides.attribute("type") ? overrides : node;
        test.type = types_.intern(typeOf(typed, testTypes));
        test.param = value(given.param);
        test.environment = value(given.environment);
        if (given.name) {
            test.name = trim(value(given.name));
        }
        if (given.repetition) {
            test.repetition = repetitionOf(node, value(given.repetition));
        } else {
            test.repetition = 0;  // not given: the command line or the default decides
        }
        if (given.timeout) {
            test.timeout = secondsOf(node, value(given.timeout), "timeout");
        }
        if (given.depends) {
            test.depends = splitList(value(given.depends));
        }
        if (given.tags) {
            test.tags = splitList(value(given.tags));
        }
        return test;
    }

    // A <test> with <parametrize name="NAME">V1, V2</parametrize> children: one test per
    // combination of the values, ${NAME} standing for the value in its plug-in and attributes,
    // each named "BASE[LABEL]" (parametrize.h) so its id is its own.
    void readParametrized(pugi::xml_node node, std::vector<TestSpec>& tests) {
        if (node.attribute("file")) {
            fail(node.child("parametrize"),
                 "<parametrize> inside <test file=\"...\">; write the parametrized test in the "
                 "suite, <test param=\"--speed ${speed}\">PLUGIN<parametrize "
                 "name=\"speed\">10, 20</parametrize></test>");
        }
        std::vector<ParameterAxis> axes;
        std::string plugin;
        std::size_t count = 1;
        for (pugi::xml_node child : node.children()) {
            if (child.type() == pugi::node_pcdata || child.type() == pugi::node_cdata) {
                plugin += child.value();
                continue;
            }
            if (child.type() != pugi::node_element) {
                continue;
            }
            if (std::string(child.name()) != "parametrize") {
                fail(child, "<" + std::string(child.name()) +
                                "> inside <test>; a <test> holds its plug-in as text and "
                                "<parametrize name=\"NAME\">V1, V2</parametrize> elements");
            }
            checkAttributes(child, {"name"});
            ParameterAxis axis;
            axis.name = trim(child.attribute("name").value());
            if (!variables::isVariableName(axis.name)) {
                fail(child, "<parametrize name=\"" + axis.name +
                                "\">: a name is letters, digits, _, - and ., not starting with "
                                "a digit (e.g. <parametrize name=\"speed\">10, 20</parametrize>)");
            }
            for (const auto& other : axes) {
                if (other.name == axis.name) {
                    fail(child, "<parametrize name=\"" + axis.name +
                                    "\"> given twice in one <test>; give each name once");
                }
            }
            axis.values = parameterValues(textOf(child));
            if (axis.values.empty()) {
                fail(child, "<parametrize name=\"" + axis.name +
                                "\"> without values; expected values separated by commas "
                                "(e.g. 10, 20)");
            }
            count *= axis.values.size();
            if (count > maxParametrizedInstances) {
                fail(child, "<parametrize> makes more than " +
                                std::to_string(maxParametrizedInstances) +
                                " instances of one <test>; expected fewer values");
            }
            axes.push_back(std::move(axis));
        }
        plugin = trim(plugin);
        if (plugin.empty()) {
            fail(node,
                 "<test> without a plug-in; write its file name as the element's text "
                 "beside its <parametrize> elements");
        }
        const std::vector<ParameterInstance> instances = instancesOf(axes);
        const std::size_t first = tests.size();
        std::vector<std::string> params;
        for (const auto& instance : instances) {
            instance_ = &instance;
            try {
                tests.push_back(readTest(node, expand(node, substituteAxes(plugin, instance))));
            } catch (...) {
                instance_ = nullptr;
                throw;
            }
            instance_ = nullptr;
            params.push_back(tests.back().param.str());
        }
        // A name="..." that says the values names each instance itself.
        const std::string named = node.attribute("name").value();
        if (!named.empty() && usesAxis(named, instances.front())) {
            return;
        }
        const std::vector<std::string> labels = instanceLabels(params, instances);
        for (std::size_t i = 0; i < instances.size(); ++i) {
            TestSpec& test = tests[first + i];
            const std::string base =
                test.name.empty() ? pluginIdPart(test.plugin, folder_) : test.name.str();
            test.name = base + "[" + labels[i] + "]";
        }
    }

    // <test file="tests/left_arm.xml" .../>: the file is found from this suite's folder and
    // read with this suite's variables over its own defaults.
    TestSpec readTestFile(pugi::xml_node node) {
        checkAttributes(node, {"file", "type", "param", "environment", "repetition", "name",
                               "timeout", "depends", "tags"});
        if (!textOf(node).empty()) {
            fail(node,
                 "<test file=\"...\"> with a plug-in as text; the test file names the "
                 "plug-in, write <test file=\"...\"/>");
        }
        const std::string file = trim(expand(node, node.attribute("file").value()));
        if (file.empty()) {
            fail(node, "<test file=\"\"> names no file; expected the path of a test file");
        }
        const std::string path = file[0] == '/' ? file : folder_ + "/" + file;
        std::string text;
        try {
            text = readBoundedFile(path, "test file");
        } catch (const SuiteFileError& e) {
            fail(node, "<test file=\"" + file + "\">: " + e.what());
        }
        variables::VariableTable table = table_;  // the suite's and the command line's
        table.resetTotal();
        SuiteReader reader(text, path, warnings_, table);
        try {
            pugi::xml_document document;
            TestSpec test = reader.readTestDocument(reader.parseRoot(document, "<test>"), node);
            for (const auto& name : table.used()) {
                usedInTestFiles_.push_back(name);
            }
            return test;
        } catch (const SuiteFileError& e) {
            fail(node, "in the test file named here: " + std::string(e.what()));
        }
    }

public:
    // The one root element of the document, parsed into `document`; `expected` names it.
    pugi::xml_node parseRoot(pugi::xml_document& document, const std::string& expected) {
        pugi::xml_parse_result parsed = document.load_buffer(
            text_.data(), text_.size(), pugi::parse_default, pugi::encoding_auto);
        if (!parsed) {
            fail(parsed.offset, std::string("malformed XML: ") + parsed.description());
        }
        pugi::xml_node root;
        for (pugi::xml_node node : document.children()) {
            if (node.type() == pugi::node_element) {
                if (root) {
                    fail(node, "a second root element <" + std::string(node.name()) +
                                   ">; the file holds one " + expected);
                }
                root = node;
            } else if (node.type() == pugi::node_pcdata || node.type() == pugi::node_cdata) {
                fail(node, "text outside the " + expected + " element");
            }
        }
        if (!root) {
            fail(text_.size(), "no root element; expected " + expected);
        }
        return root;
    }

private:
    const std::string& text_;
    SharedString path_;  // every SourceLocation of this file holds it
    std::string folder_;
    std::vector<std::string>& warnings_;
    variables::VariableTable& table_;
    std::vector<std::size_t> newlines_;
    std::vector<std::string> usedInTestFiles_;
    mutable std::unordered_map<std::string, std::pair<SharedString, SharedString>> resolved_;
    // The entry found last: the tests of a suite mostly name the plug-in of the one before.
    mutable const std::pair<const std::string, std::pair<SharedString, SharedString>>*
        lastResolved_ = nullptr;
    std::string lastPluginText_;  // the text of the last <test> testPluginOf read
    std::string lastPlugin_;      // its plug-in
    bool haveLastPlugin_ = false;
    StringPool types_;  // "dll", "python", ...: one string each for all the tests
    const ParameterInstance* instance_ = nullptr;  // the instance readParametrized reads
};

variables::VariableTable tableOf(const std::vector<variables::Variable>& given) {
    variables::VariableTable table;
    for (const auto& variable : given) {
        table.define(variable);
    }
    return table;
}

}  // namespace

SuiteSpec parseSuite(const std::string& text, const std::string& path,
                     std::vector<std::string>& warnings,
                     const std::vector<variables::Variable>& commandLine) {
    variables::VariableTable table = tableOf(commandLine);
    SuiteReader reader(text, path, warnings, table);
    pugi::xml_document document;
    return reader.readSuite(reader.parseRoot(document, "<suite name=\"...\">"));
}

TestSpec parseTestFile(const std::string& text, const std::string& path,
                       std::vector<std::string>& warnings,
                       const std::vector<variables::Variable>& suiteVariables) {
    variables::VariableTable table = tableOf(suiteVariables);
    SuiteReader reader(text, path, warnings, table);
    pugi::xml_document document;
    return reader.readTestDocument(reader.parseRoot(document, "<test>"), pugi::xml_node());
}

SuiteSpec readSuiteFile(const std::string& path, std::vector<std::string>& warnings,
                        const std::vector<variables::Variable>& commandLine) {
    return parseSuite(readBoundedFile(path, "suite file"), path, warnings, commandLine);
}

}  // namespace runner
}  // namespace robottestingframework
