#pragma once
// A fresh folder under the system's temporary directory, removed with everything in it when the object goes
// (common/io/folder_tree.h: whatever was made in it, however deep).
#include "common/io/folder_tree.h"

#include <filesystem>
#include <string>

namespace gsv {

class TemporaryFolder {
public:
    // Named "<prefix><random hex>", created exclusively; throws gsv::Error naming the temporary directory.
    explicit TemporaryFolder(const std::string& prefix);
    ~TemporaryFolder();
    TemporaryFolder(const TemporaryFolder&) = delete;
    TemporaryFolder& operator=(const TemporaryFolder&) = delete;
    const std::filesystem::path& path() const { return path_; }
    // Removes it now, returning what it held; throws gsv::Error naming what could not be removed. The destructor
    // removes what is left and says on stderr what it could not (a destructor cannot throw).
    FolderUse remove();

private:
    std::filesystem::path path_;
};

}  // namespace gsv
