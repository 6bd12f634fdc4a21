#pragma once
// `gsv-grade export`: a batch's --out folder and a roster in, the file an LMS imports out (lms_export.h).
#include "grader/src/lms/lms_export.h"

#include <filesystem>
#include <string>
#include <vector>

namespace gsv {

extern const char* const kExportUsage;

struct ExportCommand {
    LmsExportOptions options;
    bool lms_given = false;
    std::filesystem::path roster;
    std::filesystem::path batch_out;  // the batch's --out (or merge's OUT)
    std::filesystem::path to;         // the file written; empty: <batch_out>/<lms>-grades.csv (.txt for Blackboard)
    bool help = false;
};

// The arguments after `gsv-grade export`. Throws gsv::Error with one line naming the option or value at fault.
ExportCommand read_export_command(const std::vector<std::string>& args);

// Runs `gsv-grade export ARGS...`: the file written, a line saying so on stdout; each problem and note a line on stderr.
// Returns gsv-grade's exit status: 0 written, 1 problems (listed; nothing written unless --allow-partial, and a roster
// that names one student twice writes nothing even then), 2 a usage error or input that cannot be read.
int run_export_command(const std::vector<std::string>& args);

}  // namespace gsv
