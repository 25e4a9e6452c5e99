// Lua 5.4 test cases: the file fills the global table TestCase (setup(param), run(), tearDown());
// the global table robottestingframework holds what the script can call. Each test gets a Lua
// state of its own, so no two tests share anything.
#include <lua.hpp>

#include <atomic>
#include <filesystem>

#include <robottestingframework/Asserter.h>
#include <robottestingframework/Exception.h>

#include "languages/language_loaders.h"
#include "languages/script_module_interface.h"

namespace robottestingframework {
namespace languages {

namespace {

enum class Stop { None, Failure, Error, Critical };

// The error value of assertFail/assertError/assertCritical: the message is kept by the test.
char g_stopSentinel;

class LuaTestCase;

LuaTestCase* owner(lua_State* L) {
    return *static_cast<LuaTestCase**>(lua_getextraspace(L));
}

// Where the Lua code that called into C is: the first Lua function up the stack from `level`.
void luaLocation(lua_State* L, int level, TestMessage& message) {
    lua_Debug info;
    for (; lua_getstack(L, level, &info); ++level) {
        lua_getinfo(L, "Sl", &info);
        if (info.currentline >= 0) {
            message.setSourceFileName(info.source[0] == '@' ? info.source + 1 : info.short_src);
            message.setSourceLineNumber(static_cast<unsigned int>(info.currentline));
            return;
        }
    }
}

TestMessage messageHere(lua_State* L, int argument) {
    TestMessage message(luaL_tolstring(L, argument, nullptr));
    lua_pop(L, 1);
    luaLocation(L, 1, message);
    return message;
}

void measure(lua_State* L, const char* name, double value, const char* unit, bool hasLow,
             double low, bool hasHigh, double high);
void attach(lua_State* L, const char* path, const char* description);

class LuaTestCase : public TestCase {
public:
    explicit LuaTestCase(const std::string& path) : TestCase(path), path_(path) {
        L_ = luaL_newstate();
        *static_cast<LuaTestCase**>(lua_getextraspace(L_)) = this;
        luaL_openlibs(L_);
    }

    ~LuaTestCase() override { lua_close(L_); }

    bool load(std::string& error) {
        openModule();
        // RTF 2.x made the table before running the file; its tests start with
        // "TestCase.setup = ...". A file that makes its own table replaces this one.
        lua_newtable(L_);
        lua_setglobal(L_, "TestCase");
        // require() finds the script's neighbours first.
        std::string folder = std::filesystem::absolute(path_).parent_path().string();
        lua_getglobal(L_, "package");
        lua_getfield(L_, -1, "path");
        std::string searchPath = folder + "/?.lua;" + folder + "/?/init.lua;" +
                                 (lua_tostring(L_, -1) ? lua_tostring(L_, -1) : "");
        lua_pop(L_, 1);
        lua_pushstring(L_, searchPath.c_str());
        lua_setfield(L_, -2, "path");
        lua_pop(L_, 1);

        if (luaL_loadfile(L_, path_.c_str()) != LUA_OK) {
            error = lua_tostring(L_, -1) ? lua_tostring(L_, -1) : "cannot load " + path_;
            lua_pop(L_, 1);
            return false;
        }
        if (!protectedCall(0, 0, error)) {
            return false;
        }
        lua_getglobal(L_, "TestCase");
        bool isTable = lua_istable(L_, -1);
        bool hasRun = isTable && lua_getfield(L_, -1, "run") == LUA_TFUNCTION;
        lua_settop(L_, 0);
        if (!isTable) {
            error = path_ + " does not fill the global table TestCase";
        } else if (!hasRun) {
            error = "TestCase of " + path_ + " has no run() function";
        }
        return isTable && hasRun;
    }

    bool setup(int /*argc*/, char** /*argv*/) override {
        if (!push("setup")) {
            return true;
        }
        lua_pushstring(L_, getParam().c_str());
        call(1, 1);
        bool ok = lua_isnil(L_, -1) || lua_toboolean(L_, -1);  // nothing returned: success
        lua_settop(L_, 0);
        return ok;
    }

    void run() override {
        if (push("run")) {
            call(0, 0);
        }
    }

    void tearDown() override {
        if (push("tearDown")) {
            call(0, 0);
        }
    }

    void interrupt() override {
        TestCase::interrupt();
        // lua_sethook may be called from another thread or a signal handler.
        lua_sethook(
            L_, [](lua_State* L, lua_Debug*) { luaL_error(L, "interrupted"); },
            LUA_MASKCOUNT | LUA_MASKCALL, 100);
    }

    // Remembered by assertFail & co, thrown once the script has unwound.
    void stop(Stop kind, const TestMessage& message) {
        stop_ = kind;
        stopMessage_ = message;
    }

    TestMessage errorLocation;  // of the last runtime error (set by the message handler)

private:
    void openModule() {
        static const luaL_Reg functions[] = {
            {"setName",
             [](lua_State* L) {
                 owner(L)->setName(luaL_checkstring(L, 1));
                 return 0;
             }},
            {"testReport",
             [](lua_State* L) {
                 Asserter::report(messageHere(L, 1), owner(L));
                 return 0;
             }},
            {"testCheck",
             [](lua_State* L) {
                 Asserter::testCheck(lua_toboolean(L, 1), messageHere(L, 2), owner(L));
                 return 0;
             }},
            // RTF 2.x's meaning for both, which its tests rely on: the test fails when the
            // condition is false.
            {"testFailIf",
             [](lua_State* L) {
                 Asserter::testFail(lua_toboolean(L, 1), messageHere(L, 2), owner(L));
                 return 0;
             }},
            // RTF 2.x's testFail(condition, message) takes the condition as text (the check as
            // it reads, shown as "checking (condition)") and always marks the test failed, the
            // test going on; a boolean condition fails it when false, as testFailIf.
            {"testFail",
             [](lua_State* L) {
                 if (lua_type(L, 1) == LUA_TBOOLEAN) {
                     Asserter::testFail(lua_toboolean(L, 1), messageHere(L, 2), owner(L));
                     return 0;
                 }
                 TestMessage message = messageHere(L, 2);
                 message.setDetail(std::string("checking (") + luaL_tolstring(L, 1, nullptr) + ")");
                 lua_pop(L, 1);
                 Asserter::testFail(false, message, owner(L));
                 return 0;
             }},
            // testMeasure(name, value [, unit [, low [, high]]]): arguments are checked before
            // any C++ object exists (a Lua error unwinds by longjmp).
            {"testMeasure",
             [](lua_State* L) {
                 const char* name = luaL_checkstring(L, 1);
                 const double value = luaL_checknumber(L, 2);
                 const char* unit = luaL_optstring(L, 3, "");
                 const bool hasLow = !lua_isnoneornil(L, 4);
                 const double low = hasLow ? luaL_checknumber(L, 4) : 0;
                 const bool hasHigh = !lua_isnoneornil(L, 5);
                 const double high = hasHigh ? luaL_checknumber(L, 5) : 0;
                 measure(L, name, value, unit, hasLow, low, hasHigh, high);
                 return 0;
             }},
            {"testAttach",
             [](lua_State* L) {
                 const char* path = luaL_checkstring(L, 1);
                 const char* description = luaL_optstring(L, 2, "");
                 attach(L, path, description);
                 return 0;
             }},
            {"assertFail", [](lua_State* L) { return raise(L, Stop::Failure); }},
            {"assertError", [](lua_State* L) { return raise(L, Stop::Error); }},
            {"assertCritical", [](lua_State* L) { return raise(L, Stop::Critical); }},
            {"getEnvironment",
             [](lua_State* L) {
                 lua_pushstring(L, owner(L)->getEnvironment().c_str());
                 return 1;
             }},
            {"getParam",
             [](lua_State* L) {
                 lua_pushstring(L, owner(L)->getParam().c_str());
                 return 1;
             }},
            {nullptr, nullptr}};
        luaL_newlib(L_, functions);
        lua_setglobal(L_, "robottestingframework");
    }

    static int raise(lua_State* L, Stop kind) {
        owner(L)->stop(kind, messageHere(L, 1));
        lua_pushlightuserdata(L, &g_stopSentinel);
        return lua_error(L);
    }

    // A runtime error gets the traceback; assertFail & co pass through untouched.
    static int messageHandler(lua_State* L) {
        if (lua_touserdata(L, 1) == &g_stopSentinel) {
            return 1;
        }
        const char* text = lua_tostring(L, 1);
        if (text == nullptr) {
            if (luaL_callmeta(L, 1, "__tostring") && lua_type(L, -1) == LUA_TSTRING) {
                text = lua_tostring(L, -1);
            } else {
                text = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
            }
        }
        owner(L)->errorLocation = TestMessage(text);
        luaLocation(L, 1, owner(L)->errorLocation);
        luaL_traceback(L, L, text, 1);
        return 1;
    }

    // Pushes TestCase[name] when it is a function.
    bool push(const char* name) {
        lua_settop(L_, 0);
        lua_getglobal(L_, "TestCase");
        if (!lua_istable(L_, -1) || lua_getfield(L_, -1, name) != LUA_TFUNCTION) {
            lua_settop(L_, 0);
            return false;
        }
        lua_remove(L_, 1);
        return true;
    }

    // Calls the function under its arguments; false with the traceback in `error` on error.
    bool protectedCall(int arguments, int results, std::string& error) {
        int base = lua_gettop(L_) - arguments;
        lua_pushcfunction(L_, messageHandler);
        lua_insert(L_, base);
        stop_ = Stop::None;
        int status = lua_pcall(L_, arguments, results, base);
        lua_remove(L_, base);
        if (status == LUA_OK) {
            return true;
        }
        if (lua_touserdata(L_, -1) == &g_stopSentinel) {
            error = stopMessage_.getMessage();
        } else {
            error = lua_tostring(L_, -1) ? lua_tostring(L_, -1) : "error in " + path_;
        }
        lua_pop(L_, 1);
        return false;
    }

    // Like protectedCall, but errors become the framework's exceptions.
    void call(int arguments, int results) {
        std::string error;
        bool ok = protectedCall(arguments, results, error);
        if (ok && stop_ == Stop::None) {
            return;
        }
        // An assertion counts even when the script caught it with pcall.
        lua_settop(L_, 0);
        switch (stop_) {
            case Stop::Failure:
                throw TestFailureException(stopMessage_);
            case Stop::Error:
                throw TestErrorException(stopMessage_);
            case Stop::Critical:
                throw TestCriticalErrorException(stopMessage_);
            case Stop::None:
                break;
        }
        // The traceback starts with the message, which the report shows already: once is
        // enough, so the detail keeps the traceback only.
        TestMessage message = errorLocation;
        const std::string& text = message.getMessage();
        if (!text.empty() && error.compare(0, text.size(), text) == 0) {
            error.erase(0, text.size());
            error.erase(0, error.find_first_not_of('\n'));
        }
        message.setDetail(error);
        throw TestErrorException(message);
    }

    lua_State* L_;
    std::string path_;
    Stop stop_ = Stop::None;
    TestMessage stopMessage_;
};

class LoadedLuaTest : public LoadedTest {
public:
    explicit LoadedLuaTest(std::unique_ptr<LuaTestCase> test) : test_(std::move(test)) {}
    TestCase* get() override { return test_.get(); }

private:
    std::unique_ptr<LuaTestCase> test_;
};

void measure(lua_State* L, const char* name, double value, const char* unit, bool hasLow,
             double low, bool hasHigh, double high) {
    Measurement measurement;
    measurement.name = name;
    measurement.value = value;
    measurement.unit = unit;
    if (hasLow) {
        measurement.low = low;
    }
    if (hasHigh) {
        measurement.high = high;
    }
    TestMessage where;
    luaLocation(L, 1, where);
    Asserter::testMeasure(measurement, where, owner(L));
}

void attach(lua_State* L, const char* path, const char* description) {
    TestMessage where;
    luaLocation(L, 1, where);
    Asserter::testAttach(path, description, where, owner(L));
}

}  // namespace

std::unique_ptr<LoadedTest> loadLuaTest(const std::string& path, std::string& error) {
    auto test = std::make_unique<LuaTestCase>(path);
    if (!test->load(error)) {
        return nullptr;
    }
    return std::make_unique<LoadedLuaTest>(std::move(test));
}

// Lua keeps no state outside a test's own lua_State, and starts no thread: the pre-started
// process has only the library loaded (and warmed once), and forks as any process does.
bool prestartLua(std::string& error) {
    lua_State* L = luaL_newstate();
    if (L == nullptr) {
        error = "cannot create a Lua state (out of memory)";
        return false;
    }
    luaL_openlibs(L);
    lua_close(L);
    return true;
}

}  // namespace languages
}  // namespace robottestingframework

// The module's entry point: what test_loader.cpp finds with dlsym.
const robottestingframework::languages::LanguageModule* rtf_language_module() {
    static const robottestingframework::languages::LanguageModule module{
        robottestingframework::languages::kLanguageModuleVersion,
        robottestingframework::languages::loadLuaTest,
        nullptr,
        robottestingframework::languages::prestartLua,
        nullptr,
        nullptr,
        nullptr};
    return &module;
}
