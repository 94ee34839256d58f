// The overview picture of a survey, in metres (as the tiles are read; the
// scale bar measures metres whatever the CRS's unit): every tile's core
// outlined and named (names placed where they meet no other),
// the vehicles drawn on top (filled: green when confident, orange when not),
// the other objects (trees, buildings, walls) as blue outlines beneath them,
// labels placed where they collide with no other label (left out when no
// place is free), a legend and a scale bar. No points: at survey scale the
// detections are the picture. North (+y) is up.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "render/tile_picture.hpp"

namespace spinhash::host {

struct SurveyPictureTile {
  double min[2] = {0, 0}, max[2] = {0, 0};
  std::string name;
};

constexpr int kSurveyPictureSide = 1600;          // pixels along the survey's longer side, at most
constexpr double kSurveyMaxPixelsPerMetre = 8.0;  // small surveys are not blown up further

// Where each tile's name is drawn (x0, y0, x1, y1 in pixels, inclusive;
// x1 < x0 when no free place was found): names of overlapping tiles never
// overlap.
std::vector<std::array<int, 4>> survey_tile_labels(const std::vector<SurveyPictureTile>& tiles);

// False with *error when there is no tile or the PNG cannot be written.
bool write_survey_picture(const std::string& path, const std::vector<SurveyPictureTile>& tiles,
                          const std::vector<PictureBox>& boxes, const std::string& title, std::string* error);

}  // namespace spinhash::host
