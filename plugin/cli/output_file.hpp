// Atomic output. Every file of dst_file's dataset is written under its final
// name in a temporary folder beside it, checked there, then moved into place
// (rename, one file at a time, the dataset's main file last), so a failed or
// cancelled run leaves nothing, and a driver whose dataset is several files
// (MRF's .idx and .lrc, ENVI's .hdr) keeps the names its files refer to.
//
// Naming: dst_file <dir>/<stem>.<ext> is written in the folder
// <dir>/<stem>.mcmd-tmp-<pid>/ (pid: the writing process), as
// <stem>.<ext>, beside the work file <stem>.work.tif of a format filled
// through one; a second output of the same process and stem (mcmd_terrain's
// -hillshade t.png beside t.tif) gets <stem>.mcmd-tmp-<pid>.2/. The folder is removed at the end in every case but a kill
// (SIGKILL, power loss): the next run writing the same dst_file removes it.
#pragma once

#include <string>

namespace mcmd::cli {

// Removes the temporary folders of dst (named as above; also files named
// <stem>.mcmd-tmp-<pid>.*, and <stem>.<ext>.work.mcmd-tmp-<pid>.*, which
// earlier versions wrote) whose process no longer exists on this machine,
// never those of this process's TempOutputs.
void remove_stale_temporaries(const std::string& dst);

// Whether a TempOutput exists (a copy is being written), and removing the
// folders of those that exist: for a run abandoned from another thread
// (cancel_watchdog.hpp).
bool writing_temporaries();
void remove_active_temporaries();

class TempOutput {
 public:
  // Creates the temporary folder. Throws gdal::Failure.
  explicit TempOutput(std::string dst);
  TempOutput(const TempOutput&) = delete;
  TempOutput& operator=(const TempOutput&) = delete;
  ~TempOutput();  // removes the folder and what is left in it

  // Where the output dataset is written (its final name, in the folder).
  const std::string& path() const { return tmp_; }
  // Where a work file may be written (removed with the folder).
  std::string work_path() const;
  // Moves the (closed) output's files over dst's, replacing them; sidecars
  // of an earlier dst that the new output lacks are removed. Throws Failure.
  void commit();

 private:
  std::string dst_;
  std::string folder_;
  std::string tmp_;
};

}  // namespace mcmd::cli
