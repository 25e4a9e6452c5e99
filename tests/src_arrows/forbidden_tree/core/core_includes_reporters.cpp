// Read (never compiled) by src.arrows.check_rejects_forbidden_include: core/ may not include up.
#include "reporters/summary.h"
