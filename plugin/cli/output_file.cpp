#include "cli/output_file.hpp"

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <mutex>
#include <unistd.h>
#include <vector>

#include "cli/destination.hpp"
#include "cpl_conv.h"
#include "cpl_string.h"
#include "cpl_vsi.h"
#include "lib/errors.hpp"

namespace mcmd::cli {

namespace {

// Sidecars GDAL may write next to a dataset.
constexpr const char* kSidecars[] = {".aux.xml", ".msk", ".ovr"};
constexpr const char* kTempTag = ".mcmd-tmp-";

bool exists(const std::string& path) {
  VSIStatBufL st;
  return VSIStatL(path.c_str(), &st) == 0;
}

std::string in_folder(const std::string& folder, const std::string& name) {
  return CPLFormFilename(folder.c_str(), name.c_str(), nullptr);
}

// Calls f(path, pid) for each entry of path's folder named
// <stem of path>.mcmd-tmp-<pid>, or that followed by '.' and anything.
template <class F>
void for_each_temporary(const std::string& path, F&& f) {
  const std::string folder = folder_of(path);
  const std::string prefix = CPLGetBasename(path.c_str()) + std::string(kTempTag);
  const CPLStringList names(VSIReadDir(folder.c_str()));
  for (int i = 0; i < names.size(); ++i) {
    const std::string name = names[i];
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::size_t end = name.find_first_not_of("0123456789", prefix.size());
    if (end == prefix.size() || (end != std::string::npos && name[end] != '.')) continue;
    f(in_folder(folder, name), std::strtol(name.c_str() + prefix.size(), nullptr, 10));
  }
}

// No process of this id runs on this machine (ours excepted: what has our
// id was left by an earlier process that had it).
bool gone(long pid) { return pid == ::getpid() || (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH); }

void remove_tree(const std::string& path) {
  VSIStatBufL st;
  if (VSIStatL(path.c_str(), &st) != 0) return;
  if (VSI_ISDIR(st.st_mode))
    VSIRmdirRecursive(path.c_str());
  else
    VSIUnlink(path.c_str());
}

// The folders of the TempOutputs that exist.
std::mutex g_active_mutex;
std::vector<std::string> g_active;

void set_active(const std::string& folder, bool active) {
  const std::lock_guard lock(g_active_mutex);
  if (active)
    g_active.push_back(folder);
  else
    g_active.erase(std::remove(g_active.begin(), g_active.end(), folder), g_active.end());
}

bool is_active(const std::string& folder) {
  const std::lock_guard lock(g_active_mutex);
  return std::find(g_active.begin(), g_active.end(), folder) != g_active.end();
}

// <stem>.mcmd-tmp-<pid>, or with .2, .3, ... when an output of this process
// with the same stem is being written (-hillshade t.png beside t.tif).
std::string free_folder(const std::string& dst) {
  const std::string base = in_folder(folder_of(dst), CPLGetBasename(dst.c_str()) + std::string(kTempTag) +
                                                          std::to_string(::getpid()));
  std::string folder = base;
  for (int n = 2; is_active(folder); ++n) folder = base + "." + std::to_string(n);
  return folder;
}

void move(const std::string& from, const std::string& to) {
  errno = 0;
  if (VSIRename(from.c_str(), to.c_str()) != 0)
    throw gdal::Failure(CPLE_FileIO, "cannot move the finished output to '" + to + "': " +
                                         (errno ? std::strerror(errno) : "unknown reason"));
}

}  // namespace

bool writing_temporaries() {
  const std::lock_guard lock(g_active_mutex);
  return !g_active.empty();
}

void remove_active_temporaries() {
  const std::lock_guard lock(g_active_mutex);
  for (const std::string& folder : g_active) remove_tree(folder);
}

void remove_stale_temporaries(const std::string& dst) {
  const auto remove_if_gone = [](const std::string& path, long pid) {
    if (gone(pid) && !is_active(path)) remove_tree(path);
  };
  for_each_temporary(dst, remove_if_gone);
  for_each_temporary(dst + ".work.tif", remove_if_gone);  // earlier versions' work files
}

TempOutput::TempOutput(std::string dst)
    : dst_(std::move(dst)), folder_(free_folder(dst_)), tmp_(in_folder(folder_, CPLGetFilename(dst_.c_str()))) {
  remove_tree(folder_);  // our id's, from an earlier process
  errno = 0;
  if (VSIMkdir(folder_.c_str(), 0755) != 0)
    throw gdal::Failure(CPLE_FileIO, "cannot write '" + dst_ + "': cannot create the temporary folder '" + folder_ +
                                         "': " + (errno ? std::strerror(errno) : "unknown reason"));
  set_active(folder_, true);
}

TempOutput::~TempOutput() {
  CPLPushErrorHandler(CPLQuietErrorHandler);
  remove_tree(folder_);
  CPLPopErrorHandler();
  set_active(folder_, false);
}

std::string TempOutput::work_path() const {
  return in_folder(folder_, CPLGetBasename(dst_.c_str()) + std::string(".work.tif"));
}

void TempOutput::commit() {
  const std::string main = CPLGetFilename(dst_.c_str());
  const std::string work = CPLGetFilename(work_path().c_str());
  for (const char* s : kSidecars)
    if (!exists(tmp_ + s) && exists(dst_ + s)) VSIUnlink((dst_ + s).c_str());
  const CPLStringList names(VSIReadDir(folder_.c_str()));
  const std::string dir = folder_of(dst_);
  for (int i = 0; i < names.size(); ++i) {
    const std::string name = names[i];
    if (name == "." || name == ".." || name == main || name.compare(0, work.size(), work) == 0) continue;
    move(in_folder(folder_, name), in_folder(dir, name));
  }
  move(tmp_, dst_);  // last: the dataset appears whole
}

}  // namespace mcmd::cli
