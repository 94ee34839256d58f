/* The one list of the levels an answer can be confident at, and the one
 * list of the recognizer's calibrated passes.
 *
 * A level's flag says the answer is right at that level: the object is a
 * vehicle, of the first group, of the first class, the first model. Each
 * level has its own evidence (the core computes it from a result) and its
 * own threshold per scan density, fitted by `spinhash build` from the
 * database's own models and stored in the blob's Calibration section
 * (blob format 5; docs/blob-format.md). Result::level is the most specific
 * confident level whose coarser levels are all confident and consistent.
 *
 * Entries: L(id, Name, "name", "what a confident answer at it says")
 * Ids are stored in blobs (the Calibration section's cells run over the
 * levels 1..4 in id order): only ever appended, never renumbered. Level 0,
 * none, is no calibrated level: it is what Result::level says when not even
 * the vehicle level is confident.
 *
 * Passes: P(id, Name, "name", "which settings the pass runs")
 * A pass is one run of the recognizer with its own settings; each has its
 * own table of thresholds in the Calibration section.
 *
 * Compiles as C99: no // comments inside the lists. */
#ifndef SPINHASH_ANSWER_LEVELS_H
#define SPINHASH_ANSWER_LEVELS_H

#define SPINHASH_ANSWER_LEVELS(L)                                                          \
  L(0, None, "none", "not even the vehicle level is confident")                            \
  L(1, Vehicle, "vehicle", "the object is a vehicle, not a tree, wall, crate or building") \
  L(2, Group, "group", "the vehicle is of the first group (light, heavy, armoured)")       \
  L(3, Class, "class", "the vehicle is of the first class (sedan, van, ...)")              \
  L(4, Model, "model", "the vehicle is the first model")

/* Levels with a calibrated flag: ids 1 .. SPINHASH_CALIBRATED_LEVELS. */
#define SPINHASH_ANSWER_LEVEL_COUNT 5
#define SPINHASH_CALIBRATED_LEVELS 4

#define SPINHASH_CALIBRATION_PASSES(P)                                       \
  P(0, Full, "full", "the recognizer's configured settings (the full pass)") \
  P(1, First, "first", "the cascade's first pass: the first_* settings")     \
  P(2, Agree, "agree",                                                       \
    "the cascade's stop: stopping after the first pass loses no right answer at that level")

#define SPINHASH_CALIBRATION_PASS_COUNT 3

#endif /* SPINHASH_ANSWER_LEVELS_H */
