#pragma once
namespace spinhash::cli {
const char* version();
}  // namespace spinhash::cli
