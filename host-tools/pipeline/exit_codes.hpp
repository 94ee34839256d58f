// Exit statuses of the spinhash commands and of spinhash-experiment
// (the contract in docs/cli.md).
#pragma once

namespace spinhash::pipeline {

constexpr int kExitOk = 0;
constexpr int kExitError = 1;        // message on stderr
constexpr int kExitCheckFailed = 3;  // ran, but a check or a query failed

}  // namespace spinhash::pipeline
