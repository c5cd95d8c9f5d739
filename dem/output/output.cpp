// VTK XML PolyData (binary, appended raw data) and CSV writers for DEM results.
#include "kerf/dem/output/output.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstdint>
#include <cstring>

#include "kerf/dem/procedures/cutting.hpp"
#include "kerf/io.hpp"
#include "kerf/units.hpp"

namespace kerf::dem {

namespace {

template <class T>
constexpr const char* vtk_type();
template <>
constexpr const char* vtk_type<double>() {
  return "Float64";
}
template <>
constexpr const char* vtk_type<std::int32_t>() {
  return "Int32";
}
template <>
constexpr const char* vtk_type<std::int64_t>() {
  return "Int64";
}
template <>
constexpr const char* vtk_type<std::uint8_t>() {
  return "UInt8";
}

/// A PolyData file with its arrays in one appended raw block: each array is a UInt64 byte count followed by
/// the values in the machine's byte order (named in the header), as VTK's XML readers expect.
class VtpFile {
 public:
  /// Opens the piece: counts of points, vertex cells and line cells.
  VtpFile(std::size_t n_points, std::size_t n_verts, std::size_t n_lines) {
    xml_ = fmt::format(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"{}\" "
        "header_type=\"UInt64\">\n<PolyData>\n<Piece NumberOfPoints=\"{}\" NumberOfVerts=\"{}\" "
        "NumberOfLines=\"{}\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n",
        std::endian::native == std::endian::little ? "LittleEndian" : "BigEndian", n_points, n_verts, n_lines);
  }
  void tag(const std::string& text) { xml_ += text + "\n"; }
  /// One data array of `n` tuples of `components` values; `value(k, c)` gives component c of tuple k.
  template <class T, class F>
  void array(const char* name, int components, std::size_t n, F value) {
    xml_ += fmt::format(
        "<DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"appended\" offset=\"{}\"/>\n",
        vtk_type<T>(), name, components, data_.size());
    const std::uint64_t bytes = n * static_cast<std::uint64_t>(components) * sizeof(T);
    append(bytes);
    for (std::size_t k = 0; k < n; ++k)
      for (int c = 0; c < components; ++c) append(static_cast<T>(value(k, c)));
  }
  /// Vertex cells 0..n-1, one per point.
  void verts(std::size_t n) {
    tag("<Verts>");
    array<std::int64_t>("connectivity", 1, n, [](std::size_t k, int) { return k; });
    array<std::int64_t>("offsets", 1, n, [](std::size_t k, int) { return k + 1; });
    tag("</Verts>");
  }
  /// Line cells: `ends(k, 0)` and `ends(k, 1)` are the points of line k.
  template <class F>
  void lines(std::size_t n, F ends) {
    tag("<Lines>");
    array<std::int64_t>("connectivity", 1, 2 * n,
                        [&](std::size_t k, int) { return ends(k / 2, static_cast<int>(k % 2)); });
    array<std::int64_t>("offsets", 1, n, [](std::size_t k, int) { return 2 * (k + 1); });
    tag("</Lines>");
  }
  void write(const std::filesystem::path& path) {
    write_file_atomically(path, xml_ + "</Piece>\n</PolyData>\n<AppendedData encoding=\"raw\">\n_" + data_ +
                                    "\n</AppendedData>\n</VTKFile>\n");
  }

 private:
  std::string xml_, data_;
  template <class T>
  void append(T v) {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &v, sizeof(T));
    data_.append(bytes, sizeof(T));
  }
};

/// Points in mm (the CSVs' unit), z = 0.
template <class X, class Y>
void points_mm(VtpFile& f, std::size_t n, X x, Y y) {
  f.tag("<Points>");
  f.array<double>("position_mm", 3, n, [&](std::size_t k, int c) {
    return c == 0 ? units::m_to_mm(x(k)) : c == 1 ? units::m_to_mm(y(k)) : 0.0;
  });
  f.tag("</Points>");
}

}  // namespace

void write_vtp_frame(const std::filesystem::path& path, const Simulation& sim, const FrameDiskArrays& extra) {
  const auto& p = sim.particles();
  const auto& b = sim.bonds();
  std::vector<std::size_t> lines;
  std::vector<std::int32_t> broken(p.size(), 0);  // per disk: its joints that are broken (retired)
  for (std::size_t k = 0; k < b.size(); ++k)
    if (b.active[k]) {
      lines.push_back(k);
    } else {
      ++broken[static_cast<std::size_t>(b.i[k])];
      ++broken[static_cast<std::size_t>(b.j[k])];
    }
  const std::size_t n = p.size(), nl = lines.size();
  VtpFile f(n, n, nl);
  points_mm(
      f, n, [&](std::size_t i) { return p.x[i]; }, [&](std::size_t i) { return p.y[i]; });
  f.tag("<PointData Scalars=\"radius_mm\">");
  if (extra.id.empty())
    f.array<std::int64_t>("id", 1, n, [](std::size_t i, int) { return i; });
  else
    f.array<std::int64_t>("id", 1, n, [&](std::size_t i, int) { return extra.id[i]; });
  f.array<double>("radius_mm", 1, n, [&](std::size_t i, int) { return units::m_to_mm(p.radius[i]); });
  f.array<double>("velocity_m_per_s", 3, n, [&](std::size_t i, int c) {
    return c == 0 ? p.vx[i] : c == 1 ? p.vy[i] : 0.0;
  });
  f.array<double>("spin_rad_per_s", 1, n, [&](std::size_t i, int) { return p.omega[i]; });
  f.array<std::int32_t>("group", 1, n, [&](std::size_t i, int) { return p.group[i]; });
  f.array<std::uint8_t>("held", 1, n, [&](std::size_t i, int) { return p.group[i] > 0 ? 1 : 0; });
  if (!extra.displacement_m.empty())
    f.array<double>("displacement_m", 3, n, [&](std::size_t i, int c) {
      return c < 2 ? extra.displacement_m[2 * i + static_cast<std::size_t>(c)] : 0.0;
    });
  f.array<std::int32_t>("broken_joints", 1, n, [&](std::size_t i, int) { return broken[i]; });
  // Force chains (issue 55 item 6): each disk's average stress from the forces on it, as a 3 x 3 tensor (z row and
  // column 0; ParaView's tensor glyphs and eigenvectors take 9 components), its pressure, the forces' sum.
  const Simulation::DiskStresses stresses = sim.disk_stresses();
  f.array<double>("stress_MPa", 9, n, [&](std::size_t i, int c) {
    const auto& s = stresses.stress_Pa[i];
    constexpr int kIndex[9] = {0, 2, -1, 2, 1, -1, -1, -1, -1};  // xx xy . / xy yy . / . . .
    return kIndex[c] < 0 ? 0.0 : units::pa_to_mpa(s[static_cast<std::size_t>(kIndex[c])]);
  });
  f.array<double>("pressure_MPa", 1, n, [&](std::size_t i, int) {
    return -0.5 * units::pa_to_mpa(stresses.stress_Pa[i][0] + stresses.stress_Pa[i][1]);
  });
  f.array<double>("contact_force_sum_N", 1, n, [&](std::size_t i, int) { return stresses.force_sum_N[i]; });
  f.tag("</PointData>\n<CellData Scalars=\"intact_elements\">");
  f.array<std::int32_t>("intact_elements", 1, n + nl,
                        [&](std::size_t c, int) { return c < n ? -1 : b.n_bonded_elements(lines[c - n]); });
  f.array<std::int64_t>("bond", 1, n + nl, [&](std::size_t c, int) {
    return c < n ? std::int64_t{-1} : static_cast<std::int64_t>(lines[c - n]);
  });
  // Each joint's force: along its centre line (tension positive) and across it; 0 on the disks' vertex cells.
  std::vector<std::array<double, 2>> joint_forces(nl);
  for (std::size_t k = 0; k < nl; ++k) joint_forces[k] = sim.joint_force(lines[k]);
  for (std::size_t part : {0u, 1u})
    f.array<double>(part == 0 ? "joint_normal_force_N" : "joint_shear_force_N", 1, n + nl,
                    [&](std::size_t c, int) { return c < n ? 0.0 : joint_forces[c - n][part]; });
  f.tag("</CellData>");
  f.verts(n);
  f.lines(nl, [&](std::size_t k, int end) { return end == 0 ? b.i[lines[k]] : b.j[lines[k]]; });
  f.write(path);
}

void write_walls_vtp(const std::filesystem::path& path, const std::vector<Wall>& walls) {
  std::vector<std::size_t> on;
  for (std::size_t w = 0; w < walls.size(); ++w)
    if (walls[w].enabled) on.push_back(w);
  const std::size_t n = on.size();
  VtpFile f(2 * n, 0, n);
  const auto end_x = [&](std::size_t k) {
    const Wall& w = walls[on[k / 2]];
    return k % 2 == 0 ? w.x0 : w.x1;
  };
  const auto end_y = [&](std::size_t k) {
    const Wall& w = walls[on[k / 2]];
    return k % 2 == 0 ? w.y0 : w.y1;
  };
  points_mm(f, 2 * n, end_x, end_y);
  f.tag("<CellData Scalars=\"wall\">");
  f.array<std::int32_t>("wall", 1, n, [&](std::size_t k, int) { return static_cast<std::int32_t>(on[k]); });
  f.array<double>("force_N", 3, n, [&](std::size_t k, int c) {
    return c == 0 ? walls[on[k]].fx : c == 1 ? walls[on[k]].fy : 0.0;
  });
  f.array<double>("velocity_m_per_s", 3, n, [&](std::size_t k, int c) {
    return c == 0 ? walls[on[k]].vx : c == 1 ? walls[on[k]].vy : 0.0;
  });
  f.tag("</CellData>");
  f.lines(n, [](std::size_t k, int end) { return 2 * k + static_cast<std::size_t>(end); });
  f.write(path);
}

void write_cracks_vtp(const std::filesystem::path& path, const std::vector<CrackEvent>& cracks,
                      std::optional<double> y_cut_m) {
  const std::size_t n = cracks.size();
  VtpFile f(n, n, 0);
  points_mm(
      f, n, [&](std::size_t i) { return cracks[i].x_m; }, [&](std::size_t i) { return cracks[i].y_m; });
  // Named as cracks.csv's columns.
  namespace k = cracks_csv_keys;
  f.tag("<PointData Scalars=\"mode\">");
  f.array<std::int32_t>(k::mode.data(), 1, n,
                        [&](std::size_t i, int) { return static_cast<std::int32_t>(cracks[i].mode); });
  f.array<double>(k::time_s.data(), 1, n, [&](std::size_t i, int) { return cracks[i].time_s; });
  f.array<double>(k::orientation_deg.data(), 1, n,
                  [&](std::size_t i, int) { return units::rad_to_deg(cracks[i].orientation_rad); });
  f.array<double>(k::length_um.data(), 1, n, [&](std::size_t i, int) { return units::m_to_um(cracks[i].length_m); });
  f.array<std::int64_t>(k::bond.data(), 1, n, [&](std::size_t i, int) { return cracks[i].bond; });
  f.array<std::int32_t>(k::element.data(), 1, n, [&](std::size_t i, int) { return cracks[i].element; });
  if (y_cut_m)  // cracks.csv's place (crack_place) as a number ParaView can colour and threshold by
    f.array<std::int32_t>(k::place.data(), 1, n, [&](std::size_t i, int) {
      return is_chip_crack(cracks[i].y_m, *y_cut_m) ? kCrackPlaceChip : kCrackPlaceSubsurface;
    });
  f.tag("</PointData>");
  f.verts(n);
  f.write(path);
}

void write_pvd(const std::filesystem::path& path,
               const std::vector<std::pair<double, std::vector<std::string>>>& frames) {
  std::string out = "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [time, files] : frames)
    for (std::size_t part = 0; part < files.size(); ++part) {
      // The part's name from its file: frame_ (disks and joints), walls_, cracks_.
      const std::string& file = files[part];
      const std::string name = file.substr(0, file.find('_'));
      out += fmt::format("<DataSet timestep=\"{}\" part=\"{}\" name=\"{}\" file=\"{}\"/>\n", time, part,
                         name == "frame" ? "particles" : name, file);
    }
  out += "</Collection>\n</VTKFile>\n";
  write_file_atomically(path, out);
}

const ResultTable<CurveSample>& lab_test_curve_columns() {
  namespace k = curve_csv_keys;
  using S = CurveSample;
  static const ResultTable<S> table{
      result_value<S>(k::time_s, "s", "time since the test began", [](const S& s) { return s.time_s; }),
      result_value<S>(k::axial_strain, "",
                      "the axial strain, positive in the loading sense (shortening in "
                      "compression)",
                      [](const S& s) { return s.axial_strain; }),
      result_value<S>(k::lateral_strain, "", "the lateral strain, positive in the loading sense",
                      [](const S& s) { return s.lateral_strain; }),
      result_number<S>(k::stress_MPa, units::kMPa, "the axial stress, positive in the loading sense",
                       [](const S& s) { return s.stress_Pa; }),
      result_value<S>(k::tension_cracks, "", "broken joint elements in tension so far",
                      [](const S& s) { return s.n_tension_cracks; }),
      result_value<S>(k::shear_cracks, "", "broken joint elements in shear so far",
                      [](const S& s) { return s.n_shear_cracks; })};
  return table;
}

const ResultTable<CrackRow>& cracks_columns() {
  namespace k = cracks_csv_keys;
  using C = CrackRow;
  static const ResultTable<C> table{
      result_value<C>(k::time_s, "s", "when the element broke", [](const C& c) { return c.crack->time_s; }),
      result_number<C>(k::x_mm, units::kMm, "the broken element's centre, x", [](const C& c) { return c.crack->x_m; }),
      result_number<C>(k::y_mm, units::kMm, "the broken element's centre, y", [](const C& c) { return c.crack->y_m; }),
      result_number<C>(k::orientation_deg, units::kDeg, "the crack line's angle from the x axis",
                       [](const C& c) { return c.crack->orientation_rad; }),
      result_number<C>(k::length_um, units::kUm, "the element's length", [](const C& c) { return c.crack->length_m; }),
      result_value<C>(k::mode, "", "`tension` or `shear`",
                      [](const C& c) { return c.crack->mode == BreakMode::tension ? "tension" : "shear"; }),
      result_value<C>(k::bond, "", "the joint's index", [](const C& c) { return c.crack->bond; }),
      result_value<C>(k::element, "", "the element's index in its joint", [](const C& c) { return c.crack->element; }),
      // Orthogonal cutting (Yang et al. 2018, Section 4): chip above the cut line, subsurface on or below it.
      result_if(
          result_value<C>(k::place, "", "a cut's only: `chip` (above the cut line) or `subsurface` (on or below it)",
                          [](const C& c) { return crack_place(c.crack->y_m, *c.y_cut_m); }),
          [](const C& c) { return c.y_cut_m.has_value(); })};
  return table;
}

std::string curve_csv(const LabTestResult& r) {
  std::string out = results_csv_header(lab_test_curve_columns());
  for (const auto& s : r.curve) out += results_csv_row(lab_test_curve_columns(), s);
  return out;
}

namespace {
std::string cracks_table(const std::vector<CrackEvent>& cracks, std::optional<double> y_cut_m) {
  std::string out = results_csv_header(cracks_columns(), {nullptr, y_cut_m});
  for (const auto& c : cracks) out += results_csv_row(cracks_columns(), {&c, y_cut_m});
  return out;
}
}  // namespace

std::string cracks_csv(const std::vector<CrackEvent>& cracks) {
  return cracks_table(cracks, std::nullopt);
}

std::string cracks_csv(const std::vector<CrackEvent>& cracks, double y_cut_m) {
  return cracks_table(cracks, y_cut_m);
}

}  // namespace kerf::dem
