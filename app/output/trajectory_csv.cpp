#include "app/output/trajectory_csv.hpp"

#include <cstdio>
#include <cstdlib>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace elbowsim {

void write_trajectory_csv(std::ostream& out, const Recording& recording) {
  const std::vector<Column>& columns = recording.columns();
  const std::size_t cols = columns.size();
  for (std::size_t c = 0; c < cols; ++c)
    out << (c ? "," : "") << columns[c].name << " [" << columns[c].unit << "]";
  out << '\n';
  // 12 significant digits: far below any modelling error, and the same bytes
  // for the same numbers on every run.
  char buffer[32];
  for (std::size_t row = 0; row < recording.rows(); ++row) {
    for (std::size_t c = 0; c < cols; ++c) {
      std::snprintf(buffer, sizeof buffer, "%.12g", recording.at(row, c));
      out << (c ? "," : "") << buffer;
    }
    out << '\n';
  }
}

namespace {

Column parse_header_cell(const std::string& cell) {
  const auto open = cell.rfind(" [");
  if (open == std::string::npos || cell.back() != ']') return {cell, ""};
  return {cell.substr(0, open), cell.substr(open + 2, cell.size() - open - 3)};
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  for (std::size_t comma; (comma = line.find(',', start)) != std::string::npos; start = comma + 1)
    cells.push_back(line.substr(start, comma - start));
  cells.push_back(line.substr(start));
  return cells;
}

}  // namespace

Recording read_trajectory_csv(std::istream& in, const std::string& file) {
  std::string line;
  if (!std::getline(in, line)) throw std::runtime_error(file + ": empty trajectory file");
  std::vector<Column> columns;
  for (const std::string& cell : split(line)) columns.push_back(parse_header_cell(cell));
  Recording rec;
  try {
    rec.layout = TrajectoryLayout::from_columns(columns);
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(file + ":1: " + e.what());
  }
  for (long number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const std::vector<std::string> cells = split(line);
    if (cells.size() != columns.size())
      throw std::runtime_error(file + ":" + std::to_string(number) + ": expected " +
                               std::to_string(columns.size()) + " values, got " +
                               std::to_string(cells.size()));
    for (const std::string& cell : cells) {
      char* end = nullptr;
      const double v = std::strtod(cell.c_str(), &end);
      if (end == cell.c_str() || *end != '\0')
        throw std::runtime_error(file + ":" + std::to_string(number) + ": not a number: \"" +
                                 cell + "\"");
      rec.values.push_back(v);
    }
  }
  return rec;
}

}  // namespace elbowsim
