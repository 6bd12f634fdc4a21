#pragma once
// Which GL renderer each lab's golden images were rendered on (grader/golden/renderer.json), written by
// `gsv-grade --update-goldens` with the goldens and read by the self-check: its report names the renderer the
// student's labs ran on beside the goldens' own, and a failing case within the margin renderers differ by is told so
// only where the two are not the same renderer.
#include <filesystem>
#include <map>
#include <string>

namespace gsv {

// Lab -> GL_RENDERER; empty when the file does not exist. Throws gsv::Error, one line naming the file, when it is
// malformed.
std::map<std::string, std::string> read_golden_renderers(const std::filesystem::path& file);
// Writes `renderers` (every lab's), sorted by lab.
void write_golden_renderers(const std::filesystem::path& file, const std::map<std::string, std::string>& renderers);

// The renderer's name without its details: "llvmpipe (LLVM 15.0.6, 256 bits)" -> "llvmpipe".
std::string renderer_family(const std::string& renderer);

}  // namespace gsv
