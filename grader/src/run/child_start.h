#pragma once
// What a child of the grader starts with, set up around fork: the environment it may see (what a GL context needs, none
// of the grader's tokens, keys or paths) and no descriptor of the grader's but those it is given. Internal to
// grader/src/run/ (ChildProcess starts children with it).
#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

// The grader's environment as the child gets it: behind the walls (`sandboxed`) only what passes to a student, with
// HOME, TMPDIR and XDG_CACHE_HOME in `working_dir`; then `additions` (NAME=value), each replacing any of its name.
std::vector<std::string> child_environment(const std::filesystem::path& working_dir, bool sandboxed,
                                           const std::vector<std::string>& additions);

// In the child, after fork: every descriptor from `first` on but `keep` closed (close_range, or where the
// kernel lacks it a walk of /proc/self/fd with raw system calls: no allocation between fork and exec).
void close_descriptors_from(int first, int keep);

}  // namespace gsv
