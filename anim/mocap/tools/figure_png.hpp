// Drawing the paper's figures as PNG images (no text: the same data is in
// the CSV files beside them): heat maps of a grid, line plots and scatter
// plots with plain axes.
#pragma once

#include <cstdint>
#include <vector>

#include "anim/mocap/capability_map.hpp"
#include "anim/tools/png.hpp"

namespace mc::anim::mocap::tools {

using mc::anim::tools::Image;

struct HeatStyle {
  int px = 10;                 // pixels per cell
  float vmin = 0, vmax = 1;    // value range of the colour scale
  bool diverging = false;      // blue (negative) - white - red (positive) instead of dark-to-light
  const std::vector<std::uint8_t>* obstacles = nullptr;  // white with a black outline
  const std::vector<std::uint8_t>* highlight = nullptr;  // cells tinted green (opponent model)
  std::vector<int> marks;      // cells marked with a cross (start, opponent, best cell)
};

// Row 0 of the image is the grid's first row (smallest y): +x to the right,
// +y (the agent's right) downwards, as on an rcssserver pitch seen from above.
Image heat_map(const MapGrid& grid, const std::vector<float>& values, const HeatStyle& style);

struct Series {
  std::vector<float> x, y;
  std::uint8_t r = 0, g = 0, b = 0;
};
// Line plot (lines = true) or scatter plot of the series over [x0,x1] x [y0,y1].
Image plot(const std::vector<Series>& series, float x0, float x1, float y0, float y1, bool lines, int w = 640,
           int h = 400);

}  // namespace mc::anim::mocap::tools
