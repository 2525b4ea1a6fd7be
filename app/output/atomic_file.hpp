// Files written under a temporary name and renamed into place, so an
// interrupted run never leaves a half-written file behind.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <vector>

namespace elbowsim {

// Calls write(stream) on "<path>.tmp.<pid>", then renames it to path; on any
// error (also one thrown by write) the temporary is removed. Throws
// std::runtime_error naming the path and the system's reason ("No space left
// on device") if the file cannot be written.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write);

// Several files that belong together (a run's scenario, trajectory, events
// and summary): each is written to its temporary as it is added, and only
// commit() renames them all into place. Any error while adding (a full disk)
// removes every temporary and throws, so the folder keeps what it had before:
// never a new scenario.yaml beside an old trajectory.
class FileBatch {
 public:
  FileBatch() = default;
  FileBatch(const FileBatch&) = delete;
  FileBatch& operator=(const FileBatch&) = delete;
  ~FileBatch();  // removes temporaries not committed

  void add(const std::filesystem::path& path, const std::function<void(std::ostream&)>& write);
  // Removes `path` at commit (a file or folder an earlier run left that this one has not).
  void remove_at_commit(const std::filesystem::path& path);
  void commit();

 private:
  struct Entry {
    std::filesystem::path path, temporary;  // temporary empty: remove path
  };
  std::vector<Entry> entries_;
  void discard() noexcept;
};

}  // namespace elbowsim
