// The report's Markdown (report.md): data, width bases, agreement, one table per quantity, plots.
#include <fmt/format.h>

#include <algorithm>

#include "report_internal.hpp"

namespace kerf {

using namespace report_detail;

namespace {

/// "## Data": each data set with its source and citations, and how rows are matched.
std::string data_section(const Comparison& c) {
  const auto& spec = c.spec;
  std::string md = "## Data\n\n";
  const auto describe_set = [&](const DataSet& set, const std::string& role) {
    md += fmt::format("**{}: {}**{}\n\n", role, set.name, set.source.empty() ? "" : fmt::format(" (`{}`)", set.source));
    if (&set != &c.measured && set.source == c.measured.source && set.citations == c.measured.citations) {
      md += "> (the same file and citation as the measured data)\n\n";
    } else if (!set.citations.empty()) {
      for (const auto& line : set.citations) md += "> " + line + "  \n";
      md += "\n";
    }
  };
  describe_set(c.measured, "Measured");
  for (std::size_t p = 0; p < c.predictions.size(); ++p) {
    describe_set(c.predictions[p].data, c.predictions.size() > 1 ? fmt::format("Prediction {}", p + 1) : "Prediction");
  }
  md += fmt::format(
      "Rows are matched by their conditions ({}), numbers within a relative tolerance of {}. "
      "Errors are (predicted − measured) / measured; rows with the same conditions are replicates, "
      "compared through their mean, with ±1 SD (sample standard deviation) as the measured scatter.\n\n",
      [&] {
        std::string names;
        for (const auto& cs : spec.conditions) {
          names += (names.empty() ? "" : ", ") + plain(cs.label) +
                   (cs.numeric && !cs.unit.label.empty() ? " in " + cs.unit.label : "");
        }
        return names;
      }(),
      spec.relative_tolerance);
  return md;
}

/// "## Width basis": each quantity's basis on each side and the views compared.
std::string width_basis_section(const Comparison& c) {
  const auto& spec = c.spec;
  std::string md = "## Width basis\n\n| quantity | measured | ";
  for (std::size_t p = 0; p < c.predictions.size(); ++p) md += fmt::format("{} | ", c.predictions[p].data.name);
  md += "views |\n|---|---|";
  for (std::size_t p = 0; p < c.predictions.size(); ++p) md += "---|";
  md += "---|\n";
  for (std::size_t q = 0; q < spec.quantities.size(); ++q) {
    md += fmt::format("| {} | {} | ", plain(spec.quantities[q].label), c.measured.bases[q].describe());
    for (const auto& p : c.predictions) md += p.data.bases[q].describe() + " | ";
    std::string views;
    for (const auto& r : c.results) {
      if (r.quantity == q && r.prediction == 0)
        views += (views.empty() ? "" : ", ") + std::string(width_view_name(r.view));
    }
    md += views + " |\n";
  }
  md += "\n";
  return md;
}

/// "## Agreement": the metrics of every quantity, view and prediction.
std::string agreement_section(const Comparison& c) {
  std::string md =
      "## Agreement\n\n| quantity | view | prediction | n | mean abs error (%) | max abs error (%) | bias (%) | "
      "inside ±1 SD | inside ±2 SD |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : c.results) {
    md += fmt::format("| {} ({}) | {} | {} | {} | {:.2f} | {:.2f} | {:+.2f} | {} | {} |\n",
                      plain(c.spec.quantities[r.quantity].label), r.unit.label, width_view_name(r.view),
                      c.predictions[r.prediction].data.name, r.metrics.n, r.metrics.mean_abs_error_percent,
                      r.metrics.max_abs_error_percent, r.metrics.bias_percent,
                      r.n_with_scatter ? fmt::format("{}/{}", r.n_within_1sd, r.n_with_scatter) : "–",
                      r.n_with_scatter ? fmt::format("{}/{}", r.n_within_2sd, r.n_with_scatter) : "–");
  }
  md += "\n";
  return md;
}

/// One quantity, view and prediction: its table of groups, its metrics and the measurements it has no prediction for.
std::string quantity_section(const Comparison& c, const QuantityComparison& r) {
  const auto& spec = c.spec;
  const auto& qs = spec.quantities[r.quantity];
  std::string md = fmt::format("### {} ({}), {} — {}\n\n", plain(qs.label), r.unit.label, width_view_name(r.view),
                               c.predictions[r.prediction].data.name);
  if (!r.note.empty()) md += r.note + "\n\n";
  md += "| ";
  for (const auto& cs : spec.conditions) {
    md += plain(cs.label) + (cs.numeric && !cs.unit.label.empty() ? " (" + cs.unit.label + ")" : "") + " | ";
  }
  md += fmt::format("measured ({}) | n | SD ({}) | predicted ({}) | error (%) | inside ±1 SD |\n|", r.unit.label,
                    r.unit.label, r.unit.label);
  for (std::size_t k = 0; k < spec.conditions.size() + 6; ++k) md += "---|";
  md += "\n";
  for (const auto& g : r.groups) {
    md += "| ";
    for (std::size_t k = 0; k < spec.conditions.size(); ++k)
      md += condition_text(spec.conditions[k], g.conditions[k]) + " | ";
    md += fmt::format("{} | {} | {} | {} | {:+.2f} | {} |\n", number_text(g.measured_stats.mean / r.unit.si),
                      g.measured.size(),
                      g.has_scatter ? number_text(g.measured_stats.standard_deviation / r.unit.si) : "–",
                      number_text(g.predicted_stats.mean / r.unit.si), g.error_percent,
                      g.has_scatter ? (g.within_1sd ? "yes" : "no") : "–");
  }
  md += fmt::format("\nn = {}, mean |error| = {:.2f} %, max |error| = {:.2f} %, bias = {:+.2f} %", r.metrics.n,
                    r.metrics.mean_abs_error_percent, r.metrics.max_abs_error_percent, r.metrics.bias_percent);
  if (r.metrics.n != r.row_metrics.n) {
    md += fmt::format(" (against each of the {} measured rows: mean |error| = {:.2f} %)", r.row_metrics.n,
                      r.row_metrics.mean_abs_error_percent);
  }
  md += ".\n\n";
  if (!r.unmatched.empty()) {
    md += "Measured without a prediction: ";
    for (std::size_t k = 0; k < r.unmatched.size(); ++k) {
      md += (k ? "; " : "") + conditions_text(spec, r.unmatched[k]);
    }
    md += ".\n\n";
  }
  return md;
}

}  // namespace

std::string report_markdown(const Comparison& c, const ReportOptions& options,
                            const std::vector<std::string>& plot_files) {
  const auto& spec = c.spec;
  std::string md = fmt::format("# {}\n\n", spec.title.empty() ? "Force comparison" : spec.title);
  if (!spec.description.empty()) md += spec.description + "\n\n";
  md += data_section(c);
  md += width_basis_section(c);
  md += agreement_section(c);
  for (const auto& r : c.results) md += quantity_section(c, r);
  if (!plot_files.empty()) {
    md += "## Plots\n\n";
    const auto figures = plan_figures(c);
    for (const auto& f : figures) {
      if (std::find(plot_files.begin(), plot_files.end(), f.file) == plot_files.end()) continue;
      md += fmt::format("![{}]({})\n\n*{}*\n\n", plain(f.figure.title), f.file, f.caption);
    }
  }
  if (!options.extra_markdown.empty())
    md += options.extra_markdown + (options.extra_markdown.back() == '\n' ? "" : "\n");
  return md;
}

}  // namespace kerf
