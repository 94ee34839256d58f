// Databases of many copies of one toy vehicle, whose query features'
// candidates spread over the copies (stats.candidates.spread), and the view
// of that toy the spread tests recognise.
#pragma once
#include <cstdint>

#include "blob/aligned_bytes.hpp"
#include "spinhash/recognizer.hpp"
#include "support/toy_database.hpp"

namespace spinhash {
namespace test {

constexpr uint32_t kCopiedToy = 2;  // the toy copied

// `copies` copies of toy kCopiedToy, each moved `shift` metres further
// along x in its own frame (0: identical copies, boxes that coincide).
bool make_toy_copies(uint32_t copies, double shift, ToyDatabase* out);

// Recognises a moved, noisy partial view of toy kCopiedToy under `cfg`,
// the workspace in `ws` (the Result's ranking lives there: keep it).
Result recognize_copied_toy(const ToyDatabase& toy, const RecognizerConfig& cfg, host::AlignedBytes* ws);

}  // namespace test
}  // namespace spinhash
