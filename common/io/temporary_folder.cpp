#include "common/io/temporary_folder.h"

#include "common/core/error.h"

#include <cstdio>
#include <random>
#include <sstream>

namespace gsv {
namespace fs = std::filesystem;

TemporaryFolder::TemporaryFolder(const std::string& prefix) {
    std::random_device random;
    for (int attempt = 0; attempt < 16; ++attempt) {
        std::ostringstream name;
        name << prefix << std::hex << random() << random();
        path_ = fs::temp_directory_path() / name.str();
        std::error_code ec;
        if (fs::create_directory(path_, ec)) return;
    }
    throw Error("cannot make a temporary folder in " + fs::temp_directory_path().string());
}

FolderUse TemporaryFolder::remove() {
    if (path_.empty()) return {};
    const FolderUse removed = remove_folder(path_);
    path_.clear();
    return removed;
}

TemporaryFolder::~TemporaryFolder() {
    try {
        remove();
    } catch (const Error& e) {
        std::fprintf(stderr, "gsv: %s\n", e.what());
    }
}

}  // namespace gsv
