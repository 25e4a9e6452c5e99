// An exec test (Windows): prints TAP, one passing check per argument and a plan; "fail" as an
// argument makes that check fail, "crash" ends the program there with an access violation.
#include <cstdio>
#include <cstring>

int main(int argc, char** argv) {
    std::printf("1..%d\n", argc - 1);
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "crash") == 0) {
            std::fflush(stdout);
            volatile int* nowhere = nullptr;
            *nowhere = 1;
        }
        const bool ok = std::strcmp(argv[i], "fail") != 0;
        std::printf("%s %d - %s\n", ok ? "ok" : "not ok", i, argv[i]);
    }
    return 0;
}
