#pragma once
// Result files of the DEM: VTK PolyData frames (disks as vertices, joints as lines, walls as lines, cracks as
// points), the ParaView collection (.pvd), and the CSV tables of a test. Everything is written atomically.
// The .vtp files are VTK XML 1.0 with every array in one appended raw block (a UInt64 byte count before each
// array's values, byte order in the header), read by ParaView, OVITO and VTK; positions and lengths in mm (the
// CSVs' unit), the rest in the unit its name ends in (docs/dem.md, "ParaView").
//
//   write_vtp_frame(dir / "frame_0003.vtp", sim);
//   write_walls_vtp(dir / "walls_0003.vtp", sim.walls());
//   write_cracks_vtp(dir / "cracks_0003.vtp", sim.cracks());
//   write_pvd(dir / "result.pvd", {{time_s, {"frame_0003.vtp", "walls_0003.vtp", "cracks_0003.vtp"}}});
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kerf/dem/engine/simulation.hpp"
#include "kerf/dem/procedures/lab_test.hpp"
#include "kerf/result_table.hpp"

namespace kerf::dem {

/// What a particle frame shows beside the simulation's own state, one entry per disk of `sim` (both empty: the
/// disk's index in `sim` and no displacement array).
struct FrameDiskArrays {
  std::vector<std::int64_t> id;        ///< the disk's index in the run's workpiece (a windowed cut: not in its window)
  std::vector<double> displacement_m;  ///< x, y per disk: since the run's first frame (NaN: not known)
};
/// Disks (point data: id, the disk's index, the same in every frame of a run; radius_mm, velocity_m_per_s,
/// spin_rad_per_s, group: 0 free, 1 and 2 velocity prescribed; held: 1 when group > 0; displacement_m, a
/// 3-vector with z = 0, when `extra` has it; broken_joints, the disk's joints that are broken, inactive;
/// stress_MPa, the disk's average stress (Simulation::disk_stresses) as a 3 x 3 tensor, tension positive;
/// pressure_MPa, minus the mean of its xx and yy, compression positive; contact_force_sum_N, the sum of the forces'
/// magnitudes on it) and active joints (cell data: intact_elements, bond, -1 for the disks' vertex cells;
/// joint_normal_force_N, tension positive, and joint_shear_force_N, Simulation::joint_force, 0 for the disks).
void write_vtp_frame(const std::filesystem::path& path, const Simulation& sim, const FrameDiskArrays& extra = {});
/// The enabled walls (platens, the tool's faces) as lines (cell data: wall, the index; force_N, the force of
/// the disks on it; velocity_m_per_s).
void write_walls_vtp(const std::filesystem::path& path, const std::vector<Wall>& walls);
/// Crack events as points (point data: mode 1 = tension 2 = shear, time_s, orientation_deg, length_um, bond,
/// element; with a cut line `y_cut_m`, place: kCrackPlaceChip or kCrackPlaceSubsurface, as crack_place).
void write_cracks_vtp(const std::filesystem::path& path, const std::vector<CrackEvent>& cracks,
                      std::optional<double> y_cut_m = std::nullopt);
/// The crack frames' `place` codes (cracks.csv's place column: chip, subsurface).
inline constexpr std::int32_t kCrackPlaceChip = 1, kCrackPlaceSubsurface = 2;
/// A collection listing, per time, the files of that frame as parts 0, 1, ... each named by its file's
/// prefix (frame_: "particles", walls_, cracks_).
void write_pvd(const std::filesystem::path& path,
               const std::vector<std::pair<double, std::vector<std::string>>>& frames);

/// The columns of cracks.csv (cracks_columns()), one constant each; the crack frames' arrays carry the same names.
namespace cracks_csv_keys {
KERF_RESULT_KEY(time_s)
KERF_RESULT_KEY(x_mm)
KERF_RESULT_KEY(y_mm)
KERF_RESULT_KEY(orientation_deg)
KERF_RESULT_KEY(length_um)
KERF_RESULT_KEY(mode)
KERF_RESULT_KEY(bond)
KERF_RESULT_KEY(element)
KERF_RESULT_KEY(place)
}  // namespace cracks_csv_keys

/// One crack as a line of cracks.csv: the crack and, in a cut, the cut line's height (its place's).
struct CrackRow {
  const CrackEvent* crack;  ///< null in the row a header is made for
  std::optional<double> y_cut_m;
};
/// cracks.csv's columns, in order: place only in a cut's (a row with y_cut_m).
const ResultTable<CrackRow>& cracks_columns();

/// The columns of a lab test's curve.csv (lab_test_curve_columns()).
namespace curve_csv_keys {
KERF_RESULT_KEY(time_s)
KERF_RESULT_KEY(axial_strain)
KERF_RESULT_KEY(lateral_strain)
KERF_RESULT_KEY(stress_MPa)
KERF_RESULT_KEY(tension_cracks)
KERF_RESULT_KEY(shear_cracks)
}  // namespace curve_csv_keys
/// A lab test's curve.csv's columns, in order, a sample a line.
const ResultTable<CurveSample>& lab_test_curve_columns();

/// A lab test's curve.csv: lab_test_curve_columns(), a line per sample of the curve.
std::string curve_csv(const LabTestResult& result);
/// cracks.csv: cracks_columns() but place, a line per crack.
std::string cracks_csv(const std::vector<CrackEvent>& cracks);
/// A cut's cracks.csv, with place: chip (y above the cut line y_cut_m) or subsurface (orthogonal cutting).
std::string cracks_csv(const std::vector<CrackEvent>& cracks, double y_cut_m);

}  // namespace kerf::dem
