// The name of the machine the run is on, for the reports (JUnit's hostname=).
#pragma once

#include <string>

namespace robottestingframework {
namespace reporters {

// "localhost" when the system does not say.
std::string hostName();

}  // namespace reporters
}  // namespace robottestingframework
