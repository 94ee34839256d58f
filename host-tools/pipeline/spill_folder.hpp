// The temporary folders the tile stream spills a tile's points to
// (pipeline/tile_stream.hpp), named after the process that made them
// (spinhash-scene-PID-XXXXXX in the system's temporary folder), so that
// what a killed run leaves behind can be told from what a running one
// uses: folders of processes that no longer run are removed at the next
// start (remove_stale_spill_folders), and a survey interrupted by SIGINT or
// SIGTERM removes its own before it exits (survey/interrupt_cleanup.hpp).
#pragma once

#include <cstdint>
#include <string>

namespace spinhash::pipeline {

constexpr const char* kSpillFolderPrefix = "spinhash-scene-";

// Makes a new spill folder of this process and registers it; throws
// std::runtime_error when it cannot.
std::string make_spill_folder();
// Removes it (and its files) and forgets it. Never throws.
void remove_spill_folder(const std::string& path);
// Removes every spill folder this process still has (an interrupted run).
// Returns how many. Never throws.
size_t remove_own_spill_folders();

struct StaleSpill {
  size_t folders = 0;
  uint64_t bytes = 0;
};
// Removes the spill folders, in the system's temporary folder, of
// processes that no longer run. Never throws.
StaleSpill remove_stale_spill_folders();
// The same, said on stderr ("spinhash COMMAND: removed ...") when any.
void report_stale_spill_folders(const char* command);

}  // namespace spinhash::pipeline
