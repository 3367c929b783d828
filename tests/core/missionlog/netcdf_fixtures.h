#pragma once
// Small NetCDF files for the reader tests, written with the libnetcdf C API
// into the test's temp directory (there are no real .nc files in the
// repository). Deterministic: the same calls always produce the same file.
#include <netcdf.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace auv::nctest {

inline void ok(int status, const std::string& what) {
  if (status != NC_NOERR) throw std::runtime_error(what + ": " + nc_strerror(status));
}

class NcWriter {
 public:
  explicit NcWriter(const std::filesystem::path& path, int mode = NC_CLOBBER) : path_(path.string()) {
    ok(nc_create(path_.c_str(), mode, &id_), "create " + path_);
  }
  ~NcWriter() {
    if (id_ >= 0) nc_close(id_);
  }
  int dim(const std::string& name, std::size_t len) {
    int d = 0;
    ok(nc_def_dim(id_, name.c_str(), len, &d), "dim " + name);
    return d;
  }
  int var(const std::string& name, nc_type type, std::vector<int> dims) {
    int v = 0;
    ok(nc_def_var(id_, name.c_str(), type, static_cast<int>(dims.size()), dims.data(), &v), "var " + name);
    return v;
  }
  void text(int var, const std::string& att, const std::string& value) {
    ok(nc_put_att_text(id_, var, att.c_str(), value.size(), value.c_str()), "att " + att);
  }
  void number(int var, const std::string& att, nc_type type, double value) {
    ok(nc_put_att_double(id_, var, att.c_str(), type, 1, &value), "att " + att);
  }
  void endDefine() { ok(nc_enddef(id_), "enddef"); }
  void put(int var, const std::vector<double>& v) { ok(nc_put_var_double(id_, var, v.data()), "put"); }
  void putText(int var, const std::string& v) { ok(nc_put_var_text(id_, var, v.data()), "put text"); }
  void close() {
    ok(nc_close(id_), "close");
    id_ = -1;
  }

 private:
  std::string path_;
  int id_ = -1;
};

}  // namespace auv::nctest
