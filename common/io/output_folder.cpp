#include "common/io/output_folder.h"

#include "common/core/error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>

namespace fs = std::filesystem;

namespace gsv {

void prepare_output_folder(const fs::path& folder, const std::string& option) {
    const fs::path shown = folder.empty() ? fs::path(".") : folder;
    auto refuse = [&](const std::string& why) {
        throw Error(option + ": cannot write into folder '" + shown.string() + "': " + why);
    };
    std::error_code ec;
    if (fs::exists(shown, ec) && !fs::is_directory(shown, ec)) refuse("it is a file, not a folder");
    fs::create_directories(shown, ec);
    if (ec) refuse(ec.message());
    // Permission bits do not tell (root ignores them, a read-only mount keeps them): write a file and remove it.
    const fs::path probe = shown / ".gsv-write-check";
    std::FILE* file = std::fopen(probe.string().c_str(), "wb");
    if (!file) refuse(std::strerror(errno));
    std::fclose(file);
    fs::remove(probe, ec);
}

void prepare_output_file(const fs::path& file, const std::string& option) {
    std::error_code ec;
    if (fs::is_directory(file, ec)) throw Error(option + ": '" + file.string() + "' is a folder; name the file to write");
    prepare_output_folder(file.parent_path(), option);
}

}  // namespace gsv
