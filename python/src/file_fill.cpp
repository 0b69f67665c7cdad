#include "file_fill.hpp"

#include "cli/args.hpp"
#include "cli/error_log.hpp"
#include "cli/run.hpp"

namespace mcmd::python {

namespace {

// run() takes a GDAL progress function and passes it no argument of ours:
// the callback of the fill running on this thread is found here.
thread_local const ProgressFn* t_progress = nullptr;

int CPL_STDCALL to_progress_fn(double fraction, const char*, void*) {
  return !*t_progress || (*t_progress)(fraction) ? TRUE : FALSE;
}

class ProgressScope {
 public:
  explicit ProgressScope(const ProgressFn& fn) : previous_(t_progress) { t_progress = &fn; }
  ~ProgressScope() { t_progress = previous_; }
  ProgressScope(const ProgressScope&) = delete;
  ProgressScope& operator=(const ProgressScope&) = delete;

 private:
  const ProgressFn* previous_;
};

// The CLI's parser reads the flags; the file names are set afterwards so that
// a name starting with '-' is never taken for a flag.
cli::Args parse(const std::vector<std::string>& flags, const std::string& src, const std::string& dst) {
  std::vector<const char*> argv{"mcmd_fillnodata"};
  for (const std::string& f : flags) argv.push_back(f.c_str());
  argv.push_back("src_file");
  cli::Args args = cli::parse_args(static_cast<int>(argv.size()), argv.data());
  args.src = src;
  args.dst = dst;
  return args;
}

}  // namespace

void fill_file(const std::vector<std::string>& flags, const std::string& src, const std::string& dst,
               const ProgressFn& progress) {
  const cli::Args args = parse(flags, src, dst);
  const ProgressScope scope(progress);
  cli::ErrorLog log;
  cli::run(args, log, &to_progress_fn);
}

}  // namespace mcmd::python
