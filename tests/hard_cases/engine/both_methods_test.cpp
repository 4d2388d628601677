// The BothMethods tests of every file in this executable, each with the adaptive method and the
// paper's RK4. GoogleTest runs every TEST_P of a fixture once per instantiation in the executable,
// so the fixture is instantiated here, once.
#include <gtest/gtest.h>

#include "tests/support/both_integrators.hpp"

namespace blockfrag {
namespace {

using testing::BothMethods;

INSTANTIATE_TEST_SUITE_P(Integrators, BothMethods,
                         ::testing::Values(Method::adaptive, Method::rk4));

}  // namespace
}  // namespace blockfrag
