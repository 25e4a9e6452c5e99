// Read (never compiled) by src.arrows.check_rejects_forbidden_include: the public API is core's.
#include <robottestingframework/Test.h>
