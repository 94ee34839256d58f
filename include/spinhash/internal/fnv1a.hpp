// Internal interface (host tools may use it; not installed, may change):
// FNV-1a 64, the blob header's config fingerprint (spinhash/database.hpp's
// fnv1a64), in steps, for data that comes in pieces (the survey's digest of
// a database file read in chunks). One implementation, in the core.
#pragma once
#include <cstddef>
#include <cstdint>

namespace spinhash {

constexpr uint64_t kFnv1a64Basis = 0xCBF29CE484222325ull;  // the hash of no bytes

// The hash `h` continued over `size` bytes: fnv1a64(ab) ==
// fnv1a64_update(fnv1a64_update(kFnv1a64Basis, a), b).
uint64_t fnv1a64_update(uint64_t h, const void* data, size_t size) noexcept;

}  // namespace spinhash
