// The text every chapter program writes besides its figures, once: numbers in a printf
// format (figure labels, tables, plot data), the fields of a CSV line (the kept runs and
// the study's data read back), and the markdown the docs pages include. Needs nothing but
// the standard library, so the programs that draw nothing (gjkx_program) use it too.
#pragma once

#include <cmath>
#include <cstdio>
#include <ctime>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace chapter {

/// `x` printed with the printf format `spec` for one double (e.g. "%.2f", "%.1e", "%.6g").
inline std::string format(const char* spec, double x) {
  char text[128];
  std::snprintf(text, sizeof text, spec, x);
  return text;
}

/// `a` and `b` printed with the printf format `spec` for two doubles ("%.2f to %.2f").
inline std::string format(const char* spec, double a, double b) {
  char text[128];
  std::snprintf(text, sizeof text, spec, a, b);
  return text;
}

/// `x` with `digits` digits after the point: fixed(0.4567) is "0.46".
inline std::string fixed(double x, int digits = 2) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", digits, x);
  return text;
}

/// `x` in the printf format `spec`, or "-" when it is NaN (a table cell with no value).
inline std::string formatOrDash(const char* spec, double x) { return std::isnan(x) ? std::string("-") : format(spec, x); }

/// The comma-separated fields of one CSV line (no quoting: the project's CSV files have
/// none). As std::getline splits it: an empty line has no field, a trailing comma adds none.
inline std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
  return fields;
}

/// The time now, in UTC to the minute ("2025-01-31 14:05 UTC"): when a table was written.
inline std::string utcNow() {
  char text[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return text;
}

// ---- Markdown for the docs pages ---------------------------------------------------------
// The docs pages include the markdown files with Doxygen's \includedoc, which joins an
// included file into one paragraph: so a file starts with a bold title (or a table), puts
// a line break before every later title, and ends with its notes (command, run, date, what
// the columns mean), which then read as a caption under the tables.

/// A title: `bold` in bold, then `rest`; after a line break unless it is the file's first.
inline void markdownTitle(std::ostream& md, bool first, const std::string& bold, const std::string& rest = "") {
  md << (first ? "" : "\n<br>") << "**" << bold << "**" << rest << "\n\n";
}

/// The notes that end a file, read as the caption of its tables.
inline void markdownNotes(std::ostream& md, const std::string& notes) { md << "\n<br>" << notes << "\n"; }

/// A markdown table: the header's cells, then one line per row (cells as given).
inline std::string markdownTable(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  std::ostringstream out;
  out << "|";
  for (const auto& h : header) out << " " << h << " |";
  out << "\n|";
  for (std::size_t k = 0; k < header.size(); ++k) out << " --- |";
  out << "\n";
  for (const auto& row : rows) {
    out << "|";
    for (const auto& cell : row) out << " " << cell << " |";
    out << "\n";
  }
  return out.str();
}

/// Text for a markdown table cell: a '|' would end the cell.
inline std::string markdownCell(const std::string& text) {
  std::string out;
  for (const char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

}  // namespace chapter
