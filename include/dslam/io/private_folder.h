#pragma once
// A folder of this process's own under the system's temporary folder, removed with everything in
// it when the object is destroyed (the node's trajectory files when no ~trajectory_stream is set,
// so that memory stays flat over hours).

#include <string>

namespace dslam {

/// Creates `prefix` + six random characters under std::filesystem::temp_directory_path() ($TMPDIR,
/// else /tmp) with mode 0700 (mkdtemp); the destructor removes it recursively (errors ignored).
/// Throws std::runtime_error naming the folder when it cannot be created.
class PrivateFolder {
 public:
  explicit PrivateFolder(const std::string& prefix);
  ~PrivateFolder();
  PrivateFolder(const PrivateFolder&) = delete;
  PrivateFolder& operator=(const PrivateFolder&) = delete;

  /// The folder's absolute path.
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace dslam
