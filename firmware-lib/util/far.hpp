// A float beyond any coordinate, distance or score the core meets: the start
// of a running minimum (no value yet) and the answer "no finite value is
// enough".
#pragma once

namespace spinhash {

constexpr float kFar = 3.0e38f;

}  // namespace spinhash
