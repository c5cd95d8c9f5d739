#pragma once
// Result files of the DEM: VTK PolyData frames (disks as vertices, joints as lines, cracks as points),
// the ParaView collection (.pvd), and the CSV tables of a test. Everything is written atomically.
//
//   write_vtp_frame(dir / "frame_0003.vtp", sim);
//   write_cracks_vtp(dir / "cracks_0003.vtp", sim.cracks());
//   write_pvd(dir / "result.pvd", {{time_s, {"frame_0003.vtp", "cracks_0003.vtp"}}});
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "kerf/dem/lab_test.hpp"
#include "kerf/dem/simulation.hpp"

namespace kerf::dem {

/// Disks (point data: radius_m, velocity_m_per_s, spin_rad_per_s, group) and active joints (cell data:
/// intact_elements, -1 for the disks' vertex cells).
void write_vtp_frame(const std::filesystem::path& path, const Simulation& sim);
/// Crack events as points (point data: time_s, mode 1 = tension 2 = shear, orientation_deg, length_m).
void write_cracks_vtp(const std::filesystem::path& path, const std::vector<CrackEvent>& cracks);
/// A collection listing, per time, the files of that frame (as parts).
void write_pvd(const std::filesystem::path& path, const std::vector<std::pair<double, std::vector<std::string>>>& frames);

/// "time_s,axial_strain,lateral_strain,stress_MPa,tension_cracks,shear_cracks".
std::string curve_csv(const LabTestResult& result);
/// "time_s,x_mm,y_mm,orientation_deg,length_um,mode,bond,element".
std::string cracks_csv(const std::vector<CrackEvent>& cracks);
/// The same plus "place": chip (y above the cut line y_cut_m) or subsurface (orthogonal cutting).
std::string cracks_csv(const std::vector<CrackEvent>& cracks, double y_cut_m);

}  // namespace kerf::dem
