// A picture of a table image's correction, for a person to check before upload: the GRID3
// correction on slices through the lattice (per plane XY, XZ, YZ at the lower, middle and upper
// node of the third lattice axis) as magnified vectors and as colour maps per component, and each
// AXIS1D table as forward and reverse curves with their difference (the backlash).
//
// Every value comes from the firmware's own lookup (GridLookup, AxisLookup) on the validated
// image, at the nodes and between them. Positions are in mm (deg on a rotary axis), corrections
// in µm (arcsec on a rotary axis). MapTable() copies what it needs: the map does not refer to the
// image. The rendering is pure (no I/O) except WriteTableMapReport(). Colour maps use a diverging
// scale, symmetric about zero, per component over the whole lattice: t = value / limit clipped to
// [-1, 1], white (t = 0) to #B2182B (t = +1) or to #2166AC (t = -1), each channel linear in t
// and rounded to the nearest integer (docs/pc-tool.md, "volcomp inspect --report").
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/image/image_reader.hpp"
#include "volcomp/report/html_page.hpp"
#include "volcomp/tools/json_value.hpp"

namespace volcomp::image {

/// One image axis as the map shows it.
struct MapAxis {
  char name = 'X';
  bool rotary = false;
  double units_per_step = 0;   // mm (deg) per step
  double correction_unit = 0;  // µm (arcsec) per step of correction
  const char* position_unit = "mm";
  const char* correction_name = "µm";
};

/// One lattice dimension, in display units, and where the slices sample it: `samples_per_cell`
/// points per lattice cell on a small lattice, every `node_stride`-th node (and the last) on a
/// large one.
struct MapDimension {
  uint8_t axis = 0;  // index into TableMap::axes
  uint32_t nodes = 0;
  int32_t origin_steps = 0;
  uint32_t spacing_steps = 0;
  double from = 0;
  double to = 0;
  double spacing = 0;
  int samples_per_cell = 1;
  int node_stride = 1;
  std::vector<int32_t> sample_steps;  // ascending, first and last node included
  std::vector<double> sample_pos;     // the same in display units
  std::vector<int32_t> sample_node;   // the node index of a sample on a node, else -1
};

/// One slice: the plane of lattice dimensions (u, v) at a node of the third dimension w, sampled
/// at the dimensions' sample positions.
struct MapSlice {
  int u = 0, v = 1, w = 2;  // lattice dimensions
  uint32_t node = 0;        // node index along w
  const char* which = "lower";
  double position = 0;        // of that node along w, display units
  std::vector<double> value;  // (j * dim[u].sample_pos.size() + i) * 3 + c: component c
};

/// The largest |correction| of one GRID3 component and the node where it is.
struct MapExtreme {
  double min = 0, max = 0, max_abs = 0;
  std::array<uint32_t, 3> node = {0, 0, 0};
  std::array<double, 3> position = {0, 0, 0};  // display units, per lattice dimension
  double colour_limit = 1;  // the colour bar's ± limit: a round value at or above max_abs
};

/// One AXIS1D table sampled between its nodes.
struct MapAxisTable {
  uint8_t axis = 0;
  uint32_t nodes = 0;
  double from = 0, to = 0;
  bool has_reverse = false;
  uint32_t wrap_period_steps = 0;
  double backlash = 0;           // the table's constant backlash term, correction units
  std::vector<double> position;  // display units; nodes at every samples_per_cell-th sample
  std::vector<double> forward;   // correction units, moving positive
  std::vector<double> reverse;   // moving negative (reverse table or forward, + backlash)
  int samples_per_cell = 1;
};

struct TableMap {
  std::string source;  // the image's file name, for titles
  uint32_t table_id = 0;
  uint32_t crc32 = 0;
  uint32_t image_size = 0;
  std::vector<MapAxis> axes;
  bool has_grid = false;
  std::array<MapDimension, 3> dim;
  std::array<uint8_t, 3> component_axis = {0, 1, 2};  // image axis each component corrects
  std::array<MapExtreme, 3> extreme;
  double max_norm = 0;  // largest |vector| over the nodes (components in their units)
  std::array<uint32_t, 3> max_norm_node = {0, 0, 0};
  std::vector<MapSlice> slices;                         // XY lower/middle/upper, then XZ, then YZ
  std::array<double, 3> arrow_px_per_unit = {0, 0, 0};  // per plane (0 XY, 1 XZ, 2 YZ)
  std::array<double, 3> magnification = {0, 0, 0};      // per plane; 0 when not a length plot
  std::vector<MapAxisTable> axis_tables;
};

/// The map of `image` (which names `source`); kInputInvalid when the firmware's lookup refuses
/// a section.
Expected<TableMap> MapTable(const LoadedImage& image, const std::string& source);

/// The map's figures as JSON: lattice, ranges, largest |correction| per component and where,
/// slices, scale factors, AXIS1D ranges and backlash.
tools::JsonValue TableMapJson(const TableMap& map);

/// Adds the map's sections to `page`, headings from `level` (1..3).
void AddTableMapSections(report::HtmlPage* page, const TableMap& map, int level);

/// The panels of one slice as standalone <svg> elements: the vector plot, then one colour map
/// per component (dx, dy, dz in the components' order).
std::vector<std::string> SliceSvgs(const TableMap& map, const MapSlice& slice);

/// Writes DIR/index.html (DIR created if needed); returns its path.
Expected<std::string> WriteTableMapReport(const TableMap& map, const std::string& dir);

}  // namespace volcomp::image
