// The overview picture of a survey: every tile's core outlined and named,
// the vehicles drawn on top (filled: green when confident, orange when not),
// the other objects (trees, buildings, walls) as blue outlines beneath them,
// labels placed where they collide with no other label (left out when no
// place is free), a legend and a scale bar. No points: at survey scale the
// detections are the picture. North (+y) is up.
#pragma once
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

// False with *error when there is no tile or the PNG cannot be written.
bool write_survey_picture(const std::string& path, const std::vector<SurveyPictureTile>& tiles,
                          const std::vector<PictureBox>& boxes, const std::string& title, std::string* error);

}  // namespace spinhash::host
