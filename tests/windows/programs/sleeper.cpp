// A program that sleeps (10 minutes at most): the child a test leaves behind.
#include <windows.h>

int main() {
    ::Sleep(600000);
    return 0;
}
