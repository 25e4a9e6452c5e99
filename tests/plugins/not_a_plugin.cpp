// A shared library that is not a plug-in: it exports no factory.
extern "C" int not_a_plugin_answer() {
    return 42;
}
