#include "cli/csv_rows.hpp"

namespace conescan::cli {

namespace {

/// A number written earlier in the row, and where its text is.
struct written_number {
  double value;
  std::size_t from, to;
};

/// Writes a row's values (scene::visit_row) as text after the leading values, which end in ','.
class row_text {
 public:
  explicit row_text(output_sink& out) : out_(out) {}

  void real(scene::row_column column, double value) {
    using C = scene::row_column;
    switch (column) {
      case C::t_s:  // the first: no ','
        return out_.append_number(value);
      case C::head_roll_err_deg:
        return noting(value, head_roll_);
      case C::head_pitch_err_deg:
        return noting(value, head_pitch_);
      case C::roll_err_deg:
        return reusing(value, head_roll_);
      case C::pitch_err_deg:
        return reusing(value, head_pitch_);
      default:
        return field(value);
    }
  }
  void state(scene::row_column, status s) {
    out_.append(',');
    out_.append(to_string(s));
  }

 private:
  void field(double value) {
    out_.append(',');
    out_.append_number(value);
  }
  /// A head's error, its text noted when it is a number (the head measured).
  void noting(double value, written_number& noted) {
    out_.append(',');
    const std::size_t from = out_.size();
    out_.append_number(value);
    if (value == value) noted = {value, from, out_.size()};
  }
  /// A field whose value may have been written already: one measuring head's errors are the
  /// system's (simulation/simulation.cpp), and copying their text costs a tenth of formatting it
  /// again.
  void reusing(double value, const written_number& earlier) {
    if (value != earlier.value) return field(value);  // also NaN: "nan" is cheap anyway
    out_.append(',');
    out_.append_copy(earlier.from, earlier.to);
  }

  output_sink& out_;
  written_number head_roll_{not_a_number<double>(), 0, 0};  // of the last head that measured
  written_number head_pitch_{not_a_number<double>(), 0, 0};
};

// The columns' names joined by commas, ending the header line.
void write_names(output_sink& out, const std::vector<scene::column_name>& columns) {
  const char* separator = "";
  for (const scene::column_name& column : columns) {
    out.append(separator);
    out.append(column.name);
    separator = ",";
  }
  out.append('\n');
  out.end_row();
}

}  // namespace

leading_columns leading_columns::of(const scene::scene_plan& plan) {
  leading_columns leading;
  leading.layout_ = scene::leading_layout_of(plan);
  for (const scene::column_name& column : leading.layout_.columns())
    leading.names.push_back(column.name);
  leading.values.resize(leading.names.size());
  leading.condition = leading.layout_.condition;
  leading.intrusions = leading.layout_.intrusions;
  return leading;
}

void leading_columns::set(const scene::scene_plan& plan, std::uint64_t j,
                          const scene::scene_config& scene, std::uint64_t run) {
  values = scene::leading_values(layout_, plan, j, scene, run);
}

void leading_columns::write_names(output_sink& out) const {
  for (const std::string& name : names) {
    out.append(name);
    out.append(',');
  }
}

void leading_columns::write_values(output_sink& out) const {
  for (const value& v : values) {
    if (v.is_count)
      out.append_count(v.count);
    else
      out.append_number(v.real);
    out.append(',');
  }
}

void write_header(output_sink& out, std::size_t heads, const leading_columns& leading) {
  leading.write_names(out);
  write_names(out, scene::row_columns(heads, leading.condition, leading.intrusions));
}

void write_row(output_sink& out, const scene::row& row, const leading_columns& leading) {
  leading.write_values(out);
  row_text text(out);
  scene::visit_row(row, leading.condition, text, leading.intrusions);
  out.append('\n');
}

void write_budget_csv_header(output_sink& out, const std::vector<scene::budget_source>& sources) {
  write_names(out, scene::budget_columns(sources));
}

void write_budget_csv_row(output_sink& out, const scene::budget_row& row) {
  row_text text(out);
  scene::visit_budget_row(row, text);
  out.append('\n');
}

void write_summary_header(output_sink& out, const leading_columns& leading) {
  leading.write_names(out);
  write_names(out, scene::summary_columns(leading.intrusions));
}

void write_summary_line(output_sink& out, const leading_columns& leading, const std::string& source,
                        const scene::error_statistics& statistics) {
  leading.write_values(out);
  out.append(source);
  out.append(',');
  out.append_count(statistics.rows);
  for (std::uint64_t count : statistics.status_counts) {
    out.append(',');
    out.append_count(count);
  }
  for (double value : scene::summary_statistics_deg(statistics)) {
    out.append(',');
    out.append_number(value);
  }
  if (leading.intrusions)
    for (double value : scene::summary_lost_fractions(statistics)) {
      out.append(',');
      out.append_number(value);
    }
  out.append('\n');
  out.end_row();
}

}  // namespace conescan::cli
