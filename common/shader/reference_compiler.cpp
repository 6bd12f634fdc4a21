#include "common/shader/reference_compiler.h"

#include <cstdio>
#include <cstdlib>
#include <string>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/wait.h>
#include <unistd.h>
#endif

namespace gsv {
// glslangValidator is run through popen and a file made by mkstemps: POSIX only. Elsewhere there is no log, and no
// helper left unused (a warning, an error under GSV_WERROR).
#if defined(__unix__) || defined(__APPLE__)
namespace {

const char* extension(ShaderStage stage) {
    switch (stage) {
    case ShaderStage::Vertex: return ".vert";
    case ShaderStage::TessControl: return ".tesc";
    case ShaderStage::TessEval: return ".tese";
    case ShaderStage::Geometry: return ".geom";
    case ShaderStage::Fragment: return ".frag";
    case ShaderStage::Compute: return ".comp";
    }
    return ".frag";
}

}  // namespace
#endif

std::optional<std::string> reference_compiler_log(const std::string& text, ShaderStage stage) {
#if defined(__unix__) || defined(__APPLE__)
    const char* tmp = std::getenv("TMPDIR");
    std::string path = std::string(tmp && *tmp ? tmp : "/tmp") + "/gsv-glslang-XXXXXX" + extension(stage);
    const int fd = mkstemps(path.data(), 5);
    if (fd < 0) return std::nullopt;
    const bool written = write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
    close(fd);
    std::optional<std::string> log;
    if (written) {
        if (std::FILE* pipe = popen(("glslangValidator '" + path + "' 2>&1").c_str(), "r")) {
            std::string out;
            char buffer[4096];
            for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
            const int status = pclose(pipe);
            // 127: the shell found no such program.
            if (status != -1 && !(WIFEXITED(status) && WEXITSTATUS(status) == 127)) log = std::move(out);
        }
    }
    unlink(path.c_str());
    return log;
#else
    (void)text;
    (void)stage;
    return std::nullopt;
#endif
}

}  // namespace gsv
