#include "common/io/folder_tree.h"

#include "common/core/error.h"

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#if defined(__unix__) || defined(__APPLE__)
#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#define GSV_POSIX_TREES 1
#endif

namespace gsv {
namespace fs = std::filesystem;

#ifdef GSV_POSIX_TREES
namespace {

std::string why() { return std::strerror(errno); }

struct Entry {
    std::string name;
    struct stat st;
};

// The entries of the folder open as `fd` (which this takes over and closes), each with its lstat.
std::vector<Entry> entries(int fd) {
    std::vector<Entry> out;
    DIR* dir = fdopendir(fd);
    if (!dir) {
        close(fd);
        throw Error("cannot list a folder: " + why());
    }
    while (const dirent* e = readdir(dir)) {
        if (std::strcmp(e->d_name, ".") == 0 || std::strcmp(e->d_name, "..") == 0) continue;
        Entry entry{e->d_name, {}};
        if (fstatat(dirfd(dir), e->d_name, &entry.st, AT_SYMLINK_NOFOLLOW) != 0) continue;  // gone meanwhile
        out.push_back(std::move(entry));
    }
    closedir(dir);
    return out;
}

// Opens a folder below `parent` without following a link, giving it back its owner's permissions first when it
// has none (a student may leave a folder mode 000).
int open_folder(int parent, const char* name) {
    const int flags = O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC;
    int fd = openat(parent, name, flags);
    if (fd < 0 && errno == EACCES && fchmodat(parent, name, 0700, 0) == 0) fd = openat(parent, name, flags);
    if (fd >= 0) (void)fchmod(fd, 0700);
    return fd;
}

void add(FolderUse& use, const struct stat& st) {
    use.files += 1;
    use.bytes += static_cast<std::uint64_t>(st.st_blocks) * 512u;
}

}  // namespace

FolderUse measure_folder(const fs::path& folder) {
    FolderUse use;
    // Depth-first with one descriptor a level; folders are reopened relative to their parent, never by path.
    struct Level {
        int fd;
        std::vector<Entry> left;
    };
    std::vector<Level> stack;
    const int top = open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (top < 0) throw Error("cannot read the folder " + folder.string() + ": " + why());
    const int listing = dup(top);
    stack.push_back({top, listing >= 0 ? entries(listing) : std::vector<Entry>{}});
    while (!stack.empty()) {
        Level& level = stack.back();
        if (level.left.empty()) {
            close(level.fd);
            stack.pop_back();
            continue;
        }
        const Entry e = std::move(level.left.back());
        level.left.pop_back();
        add(use, e.st);
        if (!S_ISDIR(e.st.st_mode)) continue;
        if (static_cast<int>(stack.size()) > kMeasuredDepth) {
            use.too_deep = true;
            continue;
        }
        const int child = openat(level.fd, e.name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (child < 0) continue;  // no permission to look: counted as itself
        const int child_listing = dup(child);
        stack.push_back({child, child_listing >= 0 ? entries(child_listing) : std::vector<Entry>{}});
    }
    return use;
}

FolderUse remove_folder(const fs::path& folder) {
    FolderUse removed;
    struct stat st {};
    if (lstat(folder.c_str(), &st) != 0) {
        if (errno == ENOENT) return removed;
        throw Error("cannot remove " + folder.string() + ": " + why());
    }
    if (!S_ISDIR(st.st_mode)) {
        if (unlink(folder.c_str()) != 0) throw Error("cannot remove " + folder.string() + ": " + why());
        add(removed, st);
        return removed;
    }
    const int root = open_folder(AT_FDCWD, folder.c_str());
    if (root < 0) throw Error("cannot open " + folder.string() + " to remove it: " + why());
    // Each folder is emptied of its files, and its folders are moved up to the top, so no folder is ever more than
    // one below the top whatever depth the student built: a descriptor for the top and one for the folder at hand.
    std::vector<std::string> pending{"."};
    std::uint64_t moved = 0;
    std::string failure;
    while (!pending.empty() && failure.empty()) {
        const std::string name = pending.back();
        pending.pop_back();
        const bool top = name == ".";
        const int fd = top ? dup(root) : open_folder(root, name.c_str());
        if (fd < 0) {
            failure = (top ? folder.string() : name) + ": " + why();
            break;
        }
        const int listing = dup(fd);
        std::vector<Entry> inside;
        try {
            inside = entries(listing);
        } catch (const Error& e) {
            failure = e.what();
        }
        for (const Entry& e : inside) {
            const char* entry = e.name.c_str();
            if (!S_ISDIR(e.st.st_mode)) {
                if (unlinkat(fd, entry, 0) != 0) failure = e.name + ": " + why();
                else add(removed, e.st);
                continue;
            }
            if (unlinkat(fd, entry, AT_REMOVEDIR) == 0) {
                add(removed, e.st);
                continue;
            }
            if (top) {
                pending.push_back(e.name);
                continue;
            }
            const std::string flat = ".gsv-removing-" + std::to_string(moved++);
            if (renameat(fd, entry, root, flat.c_str()) != 0 &&
                !(errno == EACCES && fchmodat(fd, entry, 0700, 0) == 0 && renameat(fd, entry, root, flat.c_str()) == 0))
                failure = e.name + ": " + why();
            else
                pending.push_back(flat);
        }
        close(fd);
        if (!top && failure.empty()) {
            if (unlinkat(root, name.c_str(), AT_REMOVEDIR) != 0) failure = name + ": " + why();
            else removed.files += 1;
        }
    }
    close(root);
    if (failure.empty() && rmdir(folder.c_str()) != 0) failure = folder.string() + ": " + why();
    if (!failure.empty()) throw Error("cannot remove " + folder.string() + " (" + failure + ")");
    add(removed, st);
    return removed;
}

#else

FolderUse measure_folder(const fs::path& folder) {
    FolderUse use;
    for (auto it = fs::recursive_directory_iterator(folder); it != fs::recursive_directory_iterator(); ++it) {
        use.files += 1;
        if (it->is_regular_file()) use.bytes += it->file_size();
    }
    return use;
}

FolderUse remove_folder(const fs::path& folder) {
    FolderUse use;
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(folder, ec))) return use;
    use = measure_folder(folder);
    fs::remove_all(folder, ec);
    if (ec) throw Error("cannot remove " + folder.string() + " (" + ec.message() + ")");
    return use;
}

#endif

}  // namespace gsv
