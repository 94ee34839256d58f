// `spinhash-experiment ...`: the paper's figures (section 10) reproduced from
// data generated or loaded in memory, written as CSV + plots + summary.md.
#pragma once
#include <CLI/CLI.hpp>

namespace spinhash::experiment {

// Figure 9: P(correct model within top k) against k, per mode and condition.
void add_accuracy_experiment(CLI::App* parent, int* exit_code);
// Figure 10: time and hypotheses per query against database size; build cost.
void add_scaling_experiment(CLI::App* parent, int* exit_code);
// Eq. 2 against measured collisions; recall of the W candidates.
void add_lsh_experiment(CLI::App* parent, int* exit_code);
// Simulated airborne tiles through the scene recognizer: recall, top-1, false
// alarms and time per tile against slope, point spacing and noise.
void add_scene_experiment(CLI::App* parent, int* exit_code);
// Simulated flight lines through the SceneStream: recall, top-1, false
// alarms, duplicates and points per second against density.
void add_stream_experiment(CLI::App* parent, int* exit_code);
// Leave one world out: each world's vehicles recognised with a database of
// the other worlds' (unknown vehicles), then with every world's.
void add_worlds_experiment(CLI::App* parent, int* exit_code);
// Warzone 2100's PIE models (vehicles, structures) to OBJ meshes.
void add_prepare_warzone(CLI::App* parent, int* exit_code);
// TORCS and Trigger Rally car bodies to OBJ meshes in class folders.
void add_prepare_cars(CLI::App* parent, int* exit_code);
// Sweet Home 3D's furniture-library vehicles to OBJ meshes in class folders.
void add_prepare_sweethome3d(CLI::App* parent, int* exit_code);

// laz-speed: LAS/LAZ decoding speed and peak memory (laz_speed.cpp).
void add_laz_speed(CLI::App* parent, int* exit_code);

}  // namespace spinhash::experiment
