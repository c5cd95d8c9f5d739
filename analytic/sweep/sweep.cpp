#include "kerf/analytic/sweep/sweep.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>

#include "kerf/analytic/kinds/cells.hpp"
#include "kerf/analytic/kinds/evaluate.hpp"
#include "kerf/csv_table.hpp"
#include "kerf/error.hpp"
#include "kerf/io.hpp"

namespace kerf {

namespace {

constexpr std::size_t kMaxPoints = 50'000'000;

/// Appends the cells to one text, comma-separated, and counts them.
class CellJoiner final : public CellWriter {
 public:
  explicit CellJoiner(std::string& out) : out_(out) {}
  void cell(std::string_view, std::string_view text) override {
    if (count_++ > 0) out_ += ',';
    out_ += text;
  }
  std::size_t count() const { return count_; }

 private:
  std::string& out_;
  std::size_t count_ = 0;
};

void add_value(SweepAxis& axis, double value) {
  axis.numbers.push_back(value);
  axis.texts.push_back(fmt::format("{}", value));
  axis.values.push_back(parse_override_value(axis.texts.back()));
}

}  // namespace

SweepAxis parse_sweep_axis(const std::string& spec, const std::string& option_name) {
  const auto fail = [&](const std::string& why) { throw InputError(option_name, spec, why); };
  const auto eq = spec.find('=');
  if (eq == std::string::npos || eq == 0) fail("key.path=START:STOP:COUNT[:log] or key.path=A,B,C");
  SweepAxis axis;
  axis.key = spec.substr(0, eq);
  axis.spec = spec;
  const std::string rest = spec.substr(eq + 1);
  if (rest.find(':') == std::string::npos) {  // a list of values: A,B,C
    std::vector<std::string> texts;
    std::size_t numbers = 0;
    for (std::size_t start = 0; start <= rest.size();) {
      const std::size_t comma = std::min(rest.find(',', start), rest.size());
      texts.push_back(rest.substr(start, comma - start));
      double value = 0.0;
      numbers += parse_number(texts.back(), value) ? 1 : 0;
      start = comma + 1;
    }
    if (numbers > 0 && numbers < texts.size()) fail("a list of numbers or a list of names A,B,C, not both");
    if (numbers == 0) {  // names (models, materials) or other values, each as --set reads it
      for (const auto& text : texts)
        if (text.empty()) fail("a list of values A,B,C without an empty one");
      SweepAxis categorical = sweep_axis_from_texts(axis.key, std::move(texts));
      categorical.spec = spec;
      return categorical;
    }
    for (const auto& text : texts) {
      double value = 0.0;
      parse_number(text, value);
      add_value(axis, value);
    }
    return axis;
  }
  std::vector<std::string> parts;
  for (std::size_t start = 0;;) {
    const auto colon = rest.find(':', start);
    parts.push_back(rest.substr(start, colon == std::string::npos ? std::string::npos : colon - start));
    if (colon == std::string::npos) break;
    start = colon + 1;
  }
  if (parts.size() < 3 || parts.size() > 4 || (parts.size() == 4 && parts[3] != "log" && parts[3] != "lin")) {
    fail("START:STOP:COUNT with an optional :log or :lin");
  }
  double start = 0, stop = 0;
  long count = 0;
  try {
    std::size_t used = 0;
    start = std::stod(parts[0], &used);
    if (used != parts[0].size()) fail("a number for START");
    stop = std::stod(parts[1], &used);
    if (used != parts[1].size()) fail("a number for STOP");
    count = std::stol(parts[2], &used);
    if (used != parts[2].size()) fail("an integer COUNT");
  } catch (const std::logic_error&) {
    fail("numbers in START:STOP:COUNT");
  }
  if (!std::isfinite(start) || !std::isfinite(stop)) fail("finite START and STOP");
  if (count < 1 || count > 10'000'000) fail("COUNT in [1, 10000000]");
  axis.log_spacing = parts.size() == 4 && parts[3] == "log";
  if (axis.log_spacing && !(start > 0 && stop > 0)) fail("positive START and STOP for :log spacing");
  for (long i = 0; i < count; ++i) {
    const double f = count == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(count - 1);
    // Rounded to 15 significant digits: 0.05, not 0.049999999999999996, for a grid from 0.01 in steps of 0.01.
    const double value = axis.log_spacing ? start * std::pow(stop / start, f) : start + (stop - start) * f;
    if (!std::isfinite(value)) fail("START and STOP whose difference is finite");
    add_value(axis, std::stod(fmt::format("{:.15g}", value)));
  }
  return axis;
}

SweepAxis sweep_axis_from_texts(std::string key, std::vector<std::string> texts) {
  SweepAxis axis;
  axis.key = std::move(key);
  axis.spec = axis.key;
  for (auto& text : texts) {
    axis.values.push_back(parse_override_value(text));
    axis.texts.push_back(std::move(text));
  }
  return axis;
}

SweepGrid::SweepGrid(Json base, std::vector<SweepAxis> axes, std::string option_name)
    : base_(std::move(base)), axes_(std::move(axes)), option_name_(std::move(option_name)) {
  for (const auto& axis : axes_) {
    if (axis.values.empty()) throw InputError(option_name_ + "." + axis.key, "[]", "at least one value");
    n_points_ *= axis.values.size();
    if (n_points_ > kMaxPoints) {
      throw InputError(option_name_, axis.spec, "a grid of at most 50 million points");
    }
  }
  // The column set depends only on the models the scene asks for: the names come from the unvaried scene, or
  // with categorical axes from each combination of their values (numeric axes at their first value).
  names_ = scene_column_names(base_, &materials_);
  union_categorical_columns();
  // A key the scene does not read would refuse every point: an input error now, not a CSV of errors.
  for (const auto& axis : axes_) {
    check_varied_key(base_, axis.key + "=" + axis.texts.front(), option_name_, &materials_);
  }
  for (const auto& a : axes_) {
    for (const auto& b : axes_) {
      if (&a != &b && (a.key == b.key || b.key.starts_with(a.key + "."))) independent_keys_ = false;
    }
  }
}

void SweepGrid::union_categorical_columns() {
  std::vector<std::size_t> categorical;
  for (std::size_t a = 0; a < axes_.size(); ++a)
    if (axes_[a].numbers.empty()) categorical.push_back(a);
  if (categorical.empty()) return;
  std::size_t combinations = 1;
  for (std::size_t a : categorical) combinations *= axes_[a].values.size();
  for (std::size_t combination = 0; combination < combinations; ++combination) {
    Json document = base_;
    std::size_t rest = combination;
    for (std::size_t a = 0; a < axes_.size(); ++a) {
      std::size_t k = 0;
      if (axes_[a].numbers.empty()) k = rest % axes_[a].values.size(), rest /= axes_[a].values.size();
      apply_override(document, axes_[a].key + "=" + axes_[a].texts[k], axes_[a].values[k], option_name_);
    }
    try {
      for (auto& name : scene_column_names(document, &materials_))
        if (std::find(names_.begin(), names_.end(), name) == names_.end()) names_.push_back(std::move(name));
    } catch (const InputError&) {  // that combination's points are refused, each with its message
    } catch (const ModelError&) {
    }
  }
  varying_columns_ = true;
  for (std::size_t c = 0; c < names_.size(); ++c) column_index_.emplace(names_[c], c);
}

std::vector<std::string> SweepGrid::axis_column_names() const {
  std::vector<std::string> out;
  for (const auto& axis : axes_) {
    const bool taken = std::find(names_.begin(), names_.end(), axis.key) != names_.end();
    out.push_back(taken ? axis.key + "_varied" : axis.key);
  }
  return out;
}

std::size_t SweepGrid::stride(std::size_t a) const {
  std::size_t s = 1;
  for (std::size_t b = a + 1; b < axes_.size(); ++b) s *= axes_[b].values.size();
  return s;
}

std::size_t SweepGrid::value_index(std::size_t point, std::size_t a) const {
  return (point / stride(a)) % axes_[a].values.size();
}

void SweepGrid::evaluate(std::size_t point, Json& document, SweepRow& row, bool lists) const {
  for (std::size_t a = 0; a < axes_.size(); ++a) {
    const SweepAxis& axis = axes_[a];
    const std::size_t k = value_index(point, a);
    apply_override(document, axis.key + "=" + axis.texts[k], axis.values[k], option_name_);
  }
  const auto scene = parse_scene(document, &materials_);
  scene->predict();
  if (varying_columns_) {  // each cell to its column of the union; the columns this scene lacks stay empty
    ColumnCollector collected;
    scene->write_cells(collected);
    std::vector<std::string> cells(names_.size());
    for (auto& [name, text] : collected.columns) cells.at(column_index_.at(name)) = std::move(text);
    for (std::size_t c = 0; c < cells.size(); ++c) (row.cells += c ? "," : "") += cells[c];
    if (lists) row.guards = scene->guard_names(), row.warnings = scene->warnings();
    return;
  }
  row.cells.reserve(16 * names_.size());  // about the text of a row: one allocation, not a doubling series
  CellJoiner joiner(row.cells);
  scene->write_cells(joiner);
  if (joiner.count() != names_.size()) {
    row = SweepRow{};
    row.error = "internal: the column set changed";
    return;
  }
  if (lists) {
    row.guards = scene->guard_names();
    row.warnings = scene->warnings();
  }
}

std::vector<SweepRow> SweepGrid::run(bool lists, const std::function<void(std::size_t)>& on_progress) const {
  std::vector<SweepRow> rows(n_points_);
  // Each thread keeps its document: with independent keys, setting a point's values over the last point's
  // gives the document that base + this point's values gives (every key is set again each point). After a
  // refused point, and with keys that nest, the document starts again from the base.
  std::vector<std::optional<Json>> documents(static_cast<std::size_t>(omp_get_max_threads()));
  std::exception_ptr fault;
  std::size_t fault_point = std::numeric_limits<std::size_t>::max();
  constexpr std::size_t kChunk = 4096;
  for (std::size_t begin = 0; begin < n_points_; begin += kChunk) {
    const std::size_t end = std::min(n_points_, begin + kChunk);
#pragma omp parallel
    {
      std::optional<Json>& document = documents[static_cast<std::size_t>(omp_get_thread_num())];
#pragma omp for schedule(dynamic, 64)
      for (std::size_t i = begin; i < end; ++i) {
        const auto refuse = [&](const char* what) {
          rows[i] = SweepRow{};
          rows[i].error = what;
          document.reset();
        };
        try {
          if (!document || !independent_keys_) document = base_;
          evaluate(i, *document, rows[i], lists);
        } catch (const InputError& e) {
          refuse(e.what());
        } catch (const ModelError& e) {
          refuse(e.what());
        } catch (...) {  // a fault of the program: nothing may leave the parallel region; the first one stops the sweep
          document.reset();
#pragma omp critical(kerf_sweep_fault)
          if (i < fault_point) {
            fault_point = i;
            fault = std::current_exception();
          }
        }
      }
    }
    if (fault) std::rethrow_exception(fault);
    if (on_progress) on_progress(end - begin);
  }
  return rows;
}

std::string SweepGrid::csv_text(const std::vector<SweepRow>& rows) const {
  std::vector<std::vector<std::string>> coordinates(axes_.size());
  std::vector<std::string> header;
  const std::vector<std::string> axis_names = axis_column_names();
  for (std::size_t a = 0; a < axes_.size(); ++a) {
    header.push_back(csv_escape(axis_names[a]));
    for (std::size_t k = 0; k < axes_[a].values.size(); ++k) {
      coordinates[a].push_back(k < axes_[a].numbers.size() ? csv_number(axes_[a].numbers[k])
                                                           : csv_escape(axes_[a].texts[k]));
    }
  }
  header.insert(header.end(), names_.begin(), names_.end());
  header.push_back("error");
  std::string text = csv_line(header);
  const std::string empty_cells(names_.empty() ? 0 : names_.size() - 1, ',');
  std::size_t bytes = text.size();
  for (const auto& row : rows) bytes += row.cells.size() + row.error.size() + 16 * axes_.size() + 2;
  text.reserve(bytes + bytes / 16);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (std::size_t a = 0; a < axes_.size(); ++a) {
      if (a > 0) text += ',';
      text += coordinates[a][value_index(i, a)];
    }
    if (!axes_.empty() && !names_.empty()) text += ',';
    text += rows[i].error.empty() ? rows[i].cells : empty_cells;
    text += ',';
    text += csv_escape(rows[i].error);
    text += '\n';
  }
  return text;
}

std::vector<std::string_view> split_cells(std::string_view cells) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    std::size_t end = start;
    if (end < cells.size() && cells[end] == '"') {  // a quoted field: to the quote not doubled
      for (++end; end < cells.size(); ++end) {
        if (cells[end] != '"') continue;
        if (end + 1 < cells.size() && cells[end + 1] == '"') {
          ++end;
          continue;
        }
        ++end;
        break;
      }
    }
    end = std::min(cells.find(',', end), cells.size());
    fields.push_back(cells.substr(start, end - start));
    if (end == cells.size()) break;
    start = end + 1;
  }
  return fields;
}

std::optional<double> cell_number(std::string_view cells, std::size_t column) {
  // The field's start: past `column` commas outside quotes.
  std::size_t at = 0;
  bool quoted = false;
  for (std::size_t seen = 0; seen < column; ++at) {
    if (at == cells.size()) return std::nullopt;
    if (cells[at] == '"') quoted = !quoted;  // a doubled quote toggles twice
    if (cells[at] == ',' && !quoted) ++seen;
  }
  const std::string_view field = cells.substr(at, std::min(cells.find(',', at), cells.size()) - at);
  double value = 0.0;
  if (field.empty() || !parse_number(field, value)) return std::nullopt;
  return value;
}

}  // namespace kerf
