#pragma once
// timeseries.csv: one row per output time, SI units in the column names (time_s, kinetic_energy_J).
// On resume the file is cut back to the rows that the checkpoint had written, so the series has
// neither gaps nor duplicates.
#include <fstream>
#include <string>
#include <vector>

namespace lbdem {

class TimeSeries {
 public:
  /// Opens a new file (rows_to_keep < 0) or keeps the header and the first rows_to_keep rows.
  void open(const std::string& path, const std::vector<std::string>& columns, long rows_to_keep);
  void row(const std::vector<double>& values);
  long rows() const { return rows_; }

 private:
  std::ofstream f_;
  std::string path_;
  std::size_t ncol_ = 0;
  long rows_ = 0;
};

}  // namespace lbdem
