#include "mpi_driver/io/history_csv.hpp"

#include <charconv>
#include <sstream>

#include "mpi_driver/io/atomic_file.hpp"
#include "mpi_driver/io/output_target.hpp"

namespace blockfrag {

namespace {

void write_number(std::ostream& out, double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  out.write(buffer, result.ptr - buffer);
}

}  // namespace

void write_history_csv(std::ostream& out, const std::vector<HistoryRow>& rows) {
  out << kHistoryCsvHeader;
  for (const auto& row : rows) {
    for (const double x : {row.t, row.x, row.y, row.theta, row.vx, row.vy, row.omega}) {
      write_number(out, x);
      out << ',';
    }
    out << mode_name(row.mode) << ',';
    write_number(out, row.friction_per_weight);
    out << ',';
    write_number(out, row.normal_per_weight);
    out << '\n';
  }
}

bool is_history_csv(const std::filesystem::path& path) {
  return file_starts_with(path, kHistoryCsvHeader);
}

void write_history_csv_file(const std::filesystem::path& path,
                            const std::vector<HistoryRow>& rows) {
  std::ostringstream text;
  write_history_csv(text, rows);
  write_file_atomically(path, text.str());
}

}  // namespace blockfrag
