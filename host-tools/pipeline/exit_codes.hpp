// Exit statuses of the spinhash commands and of spinhash-experiment
// (the contract in docs/cli.md).
#pragma once

namespace spinhash::pipeline {

constexpr int kExitOk = 0;
constexpr int kExitError = 1;        // message on stderr
constexpr int kExitUsage = 2;        // bad arguments: CLI11's message and the usage on stderr
constexpr int kExitCheckFailed = 3;  // ran, but a check or a query failed

// CLI11 reports a parse error with its own code per kind (105, 106, ...);
// callers get one: 0 for --help and --version, kExitUsage otherwise.
inline int usage_exit_code(int cli11_code) { return cli11_code == 0 ? kExitOk : kExitUsage; }

}  // namespace spinhash::pipeline
