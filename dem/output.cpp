// VTK XML PolyData (ASCII) and CSV writers for DEM results.
#include "kerf/dem/output.hpp"

#include "kerf/dem/cutting.hpp"

#include <fmt/format.h>

#include "kerf/io.hpp"
#include "kerf/units.hpp"

namespace kerf::dem {

namespace {

template <class F>
void data_array(std::string& out, const char* type, const char* name, int components, std::size_t n, F value) {
  out += fmt::format("<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"ascii\">\n", type, name,
                     components);
  for (std::size_t k = 0; k < n; ++k) out += value(k);
  out += "\n</DataArray>\n";
}

}  // namespace

void write_vtp_frame(const std::filesystem::path& path, const Simulation& sim) {
  const auto& p = sim.particles();
  const auto& b = sim.bonds();
  std::vector<std::size_t> lines;
  for (std::size_t k = 0; k < b.size(); ++k)
    if (b.active[k]) lines.push_back(k);
  const std::size_t n = p.size(), nl = lines.size();
  std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n";
  out += fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"{}\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n", n, n, nl);
  out += "<Points>\n";
  data_array(out, "Float64", "position_m", 3, n, [&](std::size_t i) { return fmt::format("{} {} 0 ", p.x[i], p.y[i]); });
  out += "</Points>\n<PointData Scalars=\"radius_m\">\n";
  data_array(out, "Float64", "radius_m", 1, n, [&](std::size_t i) { return fmt::format("{} ", p.radius[i]); });
  data_array(out, "Float64", "velocity_m_per_s", 3, n, [&](std::size_t i) { return fmt::format("{} {} 0 ", p.vx[i], p.vy[i]); });
  data_array(out, "Float64", "spin_rad_per_s", 1, n, [&](std::size_t i) { return fmt::format("{} ", p.omega[i]); });
  data_array(out, "Int32", "group", 1, n, [&](std::size_t i) { return fmt::format("{} ", p.group[i]); });
  out += "</PointData>\n<CellData Scalars=\"intact_elements\">\n";
  data_array(out, "Int32", "intact_elements", 1, n + nl, [&](std::size_t c) {
    return fmt::format("{} ", c < n ? -1 : b.n_bonded_elements(lines[c - n]));
  });
  out += "</CellData>\n<Verts>\n";
  data_array(out, "Int64", "connectivity", 1, n, [&](std::size_t i) { return fmt::format("{} ", i); });
  data_array(out, "Int64", "offsets", 1, n, [&](std::size_t i) { return fmt::format("{} ", i + 1); });
  out += "</Verts>\n<Lines>\n";
  data_array(out, "Int64", "connectivity", 1, nl, [&](std::size_t k) { return fmt::format("{} {} ", b.i[lines[k]], b.j[lines[k]]); });
  data_array(out, "Int64", "offsets", 1, nl, [&](std::size_t k) { return fmt::format("{} ", 2 * (k + 1)); });
  out += "</Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  write_file_atomically(path, out);
}

void write_cracks_vtp(const std::filesystem::path& path, const std::vector<CrackEvent>& cracks) {
  const std::size_t n = cracks.size();
  std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n";
  out += fmt::format("<Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n", n, n);
  out += "<Points>\n";
  data_array(out, "Float64", "position_m", 3, n, [&](std::size_t i) { return fmt::format("{} {} 0 ", cracks[i].x_m, cracks[i].y_m); });
  out += "</Points>\n<PointData Scalars=\"mode\">\n";
  data_array(out, "Int32", "mode", 1, n, [&](std::size_t i) { return fmt::format("{} ", static_cast<int>(cracks[i].mode)); });
  data_array(out, "Float64", "time_s", 1, n, [&](std::size_t i) { return fmt::format("{} ", cracks[i].time_s); });
  data_array(out, "Float64", "orientation_deg", 1, n,
             [&](std::size_t i) { return fmt::format("{} ", units::rad_to_deg(cracks[i].orientation_rad)); });
  data_array(out, "Float64", "length_m", 1, n, [&](std::size_t i) { return fmt::format("{} ", cracks[i].length_m); });
  out += "</PointData>\n<Verts>\n";
  data_array(out, "Int64", "connectivity", 1, n, [&](std::size_t i) { return fmt::format("{} ", i); });
  data_array(out, "Int64", "offsets", 1, n, [&](std::size_t i) { return fmt::format("{} ", i + 1); });
  out += "</Verts>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  write_file_atomically(path, out);
}

void write_pvd(const std::filesystem::path& path, const std::vector<std::pair<double, std::vector<std::string>>>& frames) {
  std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [time, files] : frames)
    for (std::size_t part = 0; part < files.size(); ++part)
      out += fmt::format("<DataSet timestep=\"{}\" part=\"{}\" file=\"{}\"/>\n", time, part, files[part]);
  out += "</Collection>\n</VTKFile>\n";
  write_file_atomically(path, out);
}

std::string curve_csv(const LabTestResult& r) {
  std::string out = csv_line({"time_s", "axial_strain", "lateral_strain", "stress_MPa", "tension_cracks", "shear_cracks"});
  for (const auto& s : r.curve)
    out += csv_line({csv_number(s.time_s), csv_number(s.axial_strain), csv_number(s.lateral_strain),
                     csv_number(units::pa_to_mpa(s.stress_pa)), std::to_string(s.n_tension_cracks),
                     std::to_string(s.n_shear_cracks)});
  return out;
}

namespace {
std::string cracks_table(const std::vector<CrackEvent>& cracks, const double* y_cut_m) {
  std::vector<std::string> head{"time_s", "x_mm", "y_mm", "orientation_deg", "length_um", "mode", "bond", "element"};
  if (y_cut_m) head.push_back("place");
  std::string out = csv_line(head);
  for (const auto& c : cracks) {
    std::vector<std::string> row{csv_number(c.time_s), csv_number(units::m_to_mm(c.x_m)), csv_number(units::m_to_mm(c.y_m)),
                                 csv_number(units::rad_to_deg(c.orientation_rad)), csv_number(units::m_to_um(c.length_m)),
                                 c.mode == BreakMode::tension ? "tension" : "shear", std::to_string(c.bond),
                                 std::to_string(c.element)};
    // Orthogonal cutting (seed 000 Section 4): chip above the cut line, subsurface on or below it.
    if (y_cut_m) row.push_back(crack_place(c.y_m, *y_cut_m));
    out += csv_line(row);
  }
  return out;
}
}  // namespace

std::string cracks_csv(const std::vector<CrackEvent>& cracks) { return cracks_table(cracks, nullptr); }

std::string cracks_csv(const std::vector<CrackEvent>& cracks, double y_cut_m) { return cracks_table(cracks, &y_cut_m); }

}  // namespace kerf::dem
