// Compiled only by the src.arrows.forbidden_include_fails_to_compile test, which expects it NOT
// to compile: core/ may use platform/ only, so the reporters' headers are not on its path.
#include "core/text_safety.h"
#include "reporters/summary.h"
