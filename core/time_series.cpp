#include "core/time_series.hpp"

#include <cerrno>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"
#include "core/h5.hpp"

namespace lbdem {

void TimeSeries::open(const std::string& path, const std::vector<std::string>& columns,
                      long rows_to_keep) {
  std::string header;
  for (std::size_t i = 0; i < columns.size(); ++i) header += (i ? "," : "") + columns[i];
  ncol_ = columns.size();
  path_ = path;
  if (rows_to_keep >= 0) {
    std::ifstream in(path);
    std::string line, kept;
    std::getline(in, line);
    if (line != header)
      throw std::runtime_error(path + ": its columns differ from this build's; cannot resume");
    kept = line + "\n";
    long n = 0;
    while (n < rows_to_keep && std::getline(in, line)) kept += line + "\n", ++n;
    if (n < rows_to_keep) throw std::runtime_error(path + ": fewer rows than the checkpoint wrote");
    write_file_atomic(path, kept);
    rows_ = n;
    f_.open(path, std::ios::app);
  } else {
    f_.open(path, std::ios::trunc);
    f_ << header << '\n';
    rows_ = 0;
  }
  f_.flush();
  if (!f_) throw write_error(path, errno);
}

void TimeSeries::row(const std::vector<double>& values) {
  if (values.size() != ncol_) throw std::logic_error("time series row has the wrong width");
  char buf[32];
  for (std::size_t i = 0; i < values.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%.10g", values[i]);
    if (i) f_ << ',';
    f_ << buf;
  }
  f_ << '\n';
  errno = 0;
  f_.flush();
  if (!f_) throw write_error(path_, errno);
  ++rows_;
}

}  // namespace lbdem
