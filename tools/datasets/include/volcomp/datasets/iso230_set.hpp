// An ISO 230-1 component-error set as the exchange files hold it (Etalon exchange format,
// ISG-CSV; etalon_exchange.hpp, isg_csv.hpp) and its mapping onto the 21-parameter model
// (model/rigid_body.hpp).
//
// Names (ISO 230-1, as the ISG kernel lists them: TF5280 "List of parameters supported",
// https://isg-stuttgart.de/fileadmin/kernel/kernel-html/en-GB/296423819.html):
//   E<err><axis>   component error of <axis> (a function of <axis>'s position): err X, Y, Z
//                  linear (EXX positioning, EYX/EZX straightness), A, B, C angular (EAX roll,
//                  EBX pitch, ECX yaw of X); err and axis each one of X Y Z A B C.
//   <err>0<axis>   position (location) error, one value: C0Y squareness of Y to X, B0Z and A0Z
//                  squareness of Z to X and Y.
//   P0X..P0Z, N0X..N0Z, P<X|Y|Z><A|B|C>, V<X|Y|Z><axis>: the ISG kernel's own parameters (TCP
//                  zero, tool orientation, rotary centres, axis orientation).
// The model holds the 18 component errors of X, Y, Z and C0Y, B0Z, A0Z: 21 parameters.
//
// Units. In the files (ISG,
// https://isg-stuttgart.de/fileadmin/kernel/kernel-html/en-GB/296426379.html): linear errors mm,
// angles rad, arguments mm (deg for rotary axes). In the model: µm, µrad, mm. Sign. Both sides hold
// the error, actual − nominal (ISO 230-1 error motions; the ISG volumetric compensation subtracts
// it, data-formats.md B6/D). Angles are right-handed rotations about +x, +y, +z (ISO 230-1), so C0Y
// > 0 opens the X–Y angle beyond 90° as in the model (docs/table-builders.md §2). No sign is
// changed in either direction.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "volcomp/hosted/expected.hpp"
#include "volcomp/model/rigid_body.hpp"

namespace volcomp::datasets {

/// One parameter as a file gives it, in the file's units (mm, rad; arguments mm or deg).
struct Iso230Parameter {
  std::string name;               // upper case, e.g. "EXX", "C0Y"
  std::size_t line = 0;           // where the file defines it (0: made by code)
  bool tabulated = false;         // a table of (argument, value) rows, else one value
  std::string argument;           // the argument's axis letter when tabulated, e.g. "X"
  std::vector<double> arguments;  // increasing
  std::vector<double> values;     // one per argument; one value when not tabulated
};

struct Iso230Set {
  std::string source;  // names the file in messages
  std::vector<Iso230Parameter> parameters;
};

/// Plausibility limits of a file value (catch a file in µm or µrad read as mm or rad): a linear
/// error beyond 1 mm or an angle beyond 0.01 rad (10 000 µrad, 34') is refused.
inline constexpr double kIso230MaxLinear_mm = 1.0;
inline constexpr double kIso230MaxAngle_rad = 0.01;

enum class Iso230Kind {
  kUnknown,         // no ISO 230-1 or ISG name
  kModelComponent,  // E<err><X|Y|Z>: in the model
  kModelPosition,   // C0Y, B0Z, A0Z: in the model
  kOther,           // a name of the standard or of ISG the model has no place for
};
Iso230Kind ClassifyIso230Name(const std::string& name);

/// True for an angular parameter (E<A|B|C><axis>, <A|B|C>0<axis>): rad in the file.
bool IsIso230Angle(const std::string& name);

/// Checks a parsed set: each name known (kUnknown refused), no name twice (both lines named),
/// a component error tabulated against its own axis with increasing arguments, a position error
/// a single value, every value of the model's 21 parameters within the plausibility limits above
/// (value, limit and the likely unit named).
Outcome CheckIso230Set(const Iso230Set& set);

struct ModelFromIso230 {
  model::Model model;                 // default chain |XYZ, physical formulation, exact order
  std::vector<std::string> warnings;  // parameters taken as 0 or ignored, each named
};

/// The model of a set. Each axis's table holds the union of its component errors' arguments, each
/// function interpolated linearly between its own rows and held beyond them (as the model does, so
/// nothing changes). Refused (kInputInvalid, naming the parameter): a parameter the model has no
/// place for with a non-zero value (all zero: a warning); an axis without any tabulated component
/// error (its range is unknown). A missing component error or squareness is 0 with a warning
/// naming it. Runs CheckIso230Set first.
Expected<ModelFromIso230> ModelFromIso230Set(const Iso230Set& set);

struct Iso230FromModel {
  Iso230Set set;  // EXX..ECX, EXY..ECY, EXZ..ECZ tabulated, then C0Y, B0Z, A0Z
  /// What the files cannot hold and how it was handled, each a sentence: the chain, tool
  /// offset, formulation, order (not written), angle_scale and carriage-side errors (applied).
  std::vector<std::string> notes;
};

/// The set of a model, in file units: the errors the model applies (angles × angle_scale; the
/// functions of a workpiece-carrying axis negated when workpiece_errors = carriage). Read back, it
/// gives the same tables and squareness; the chain, tool offset and formulation are not carried
/// (`notes` names those that differ from the defaults).
Iso230FromModel Iso230SetFromModel(const model::Model& m);

}  // namespace volcomp::datasets
