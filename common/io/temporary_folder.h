#pragma once
// A fresh folder under the system's temporary directory, removed with everything in it when the object goes.
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

private:
    std::filesystem::path path_;
};

}  // namespace gsv
