#pragma once
// A lab's own tests, made for every lab of the build's list (tests/lab_runner.h: build/labs.json) as the test binary
// starts: GSV_PER_LAB_TEST("what it checks", "[tags]", function) registers "lab01: what it checks", "lab02: ...", each
// calling function("lab01"), and so on. No test file names a lab, and a lab added gets its tests, under the names and
// labels every lab's have, when the binary relinks against the new list (tests/CMakeLists.txt): nothing is compiled.
#include "catch.hpp"
#include "lab_runner.h"

#include <algorithm>
#include <cstddef>
#include <deque>
#include <string>

namespace gsv::test {

// Which labs get the test: every lab, those macOS's OpenGL 4.1 runs, or those that need 4.3 (lab.json's needs_gl).
enum class PerLab { Every, OnGl41, NeedsGl43 };
// Whether a lab that needs OpenGL 4.3 gets the tag [gl43] (its ctest label: left out where 4.3 is not to be had).
enum class Gl43Tag { Where4_3, Never };

namespace detail {

class LabTest : public Catch::ITestInvoker {
public:
    LabTest(void (*test)(const std::string&), std::string lab) : test_(test), lab_(std::move(lab)) {}
    void invoke() const override { test_(lab_); }

private:
    void (*test_)(const std::string&);
    std::string lab_;
};

inline void register_test(void (*test)(const std::string&), const std::string& lab, const std::string& name,
                          const std::string& tags, const char* file, std::size_t line) {
    // Catch keeps the name and tags by reference in places: kept here for the program's life (a deque moves none).
    static std::deque<std::string> kept;
    kept.push_back(name);
    const std::string& kept_name = kept.back();
    kept.push_back(tags);
    const std::string& kept_tags = kept.back();
#if defined(CATCH_VERSION_MAJOR) && CATCH_VERSION_MAJOR >= 3
    Catch::AutoReg(Catch::Detail::make_unique<LabTest>(test, lab), Catch::SourceLineInfo(file, line), Catch::StringRef(),
                   Catch::NameAndTags{kept_name, kept_tags});
#else
    Catch::AutoReg(new LabTest(test, lab), Catch::SourceLineInfo(file, line), Catch::StringRef(),
                   Catch::NameAndTags{kept_name, kept_tags});
#endif
}

inline void unreadable_list() { FAIL("the build's list of labs, " << lab_list_file().string() << ", cannot be read: configure again"); }

}  // namespace detail

// The test's name for a lab: `name` with "{lab}" replaced by its id, or "<id>: " before it.
inline std::string per_lab_name(const std::string& name, const std::string& lab) {
    const auto at = name.find("{lab}");
    return at == std::string::npos ? lab + ": " + name : name.substr(0, at) + lab + name.substr(at + 5);
}

// The labs a per-lab test is made for.
inline std::vector<std::string> per_lab_labs(PerLab which) {
    std::vector<std::string> labs;
    for (const LabEntry& lab : lab_list())
        if (which == PerLab::Every || (which == PerLab::OnGl41) != lab.needs_gl43()) labs.push_back(lab.id);
    return labs;
}

inline bool register_per_lab(const char* name, const char* tags, void (*test)(const std::string&), PerLab which,
                             Gl43Tag gl43, const char* file, std::size_t line) {
    try {
        for (const LabEntry& lab : lab_list()) {
            if ((which == PerLab::OnGl41 && lab.needs_gl43()) || (which == PerLab::NeedsGl43 && !lab.needs_gl43())) continue;
            const std::string more = gl43 == Gl43Tag::Where4_3 && lab.needs_gl43() ? "[gl43]" : "";
            detail::register_test(test, lab.id, per_lab_name(name, lab.id), tags + more, file, line);
        }
    } catch (const std::exception&) {
        // Once, however many tests could not be made: the list the binary was built beside is gone or broken.
        static const bool once = [] {
            Catch::AutoReg(Catch::makeTestInvoker(&detail::unreadable_list), Catch::SourceLineInfo(__FILE__, __LINE__),
                           Catch::StringRef(), Catch::NameAndTags{"the build's list of labs can be read", "[unit]"});
            return true;
        }();
        (void)once;
    }
    return true;
}

// Whether the binary has the test `name` (as GSV_PER_LAB_TEST was given it) for each lab `which` takes.
inline std::vector<std::string> labs_missing_test(const std::string& name, PerLab which) {
    std::vector<std::string> missing;
    const auto& tests = Catch::getRegistryHub().getTestCaseRegistry().getAllTests();
    for (const std::string& lab : per_lab_labs(which)) {
        const std::string wanted = per_lab_name(name, lab);
        if (std::none_of(tests.begin(), tests.end(), [&](const auto& t) { return t.getTestCaseInfo().name == wanted; }))
            missing.push_back(lab);
    }
    return missing;
}

}  // namespace gsv::test

#define GSV_PER_LAB_CONCAT2(a, b) a##b
#define GSV_PER_LAB_CONCAT(a, b) GSV_PER_LAB_CONCAT2(a, b)
// GSV_PER_LAB_TEST(name, tags, function[, which[, gl43]]): one test case per lab of the build's list (above).
#define GSV_PER_LAB_TEST(name, tags, ...)                                                                             \
    namespace {                                                                                                        \
    const bool GSV_PER_LAB_CONCAT(gsv_per_lab_test_, __LINE__) =                                                       \
        ::gsv::test::register_per_lab_at(name, tags, __FILE__, __LINE__, __VA_ARGS__);                                 \
    }
namespace gsv::test {
inline bool register_per_lab_at(const char* name, const char* tags, const char* file, std::size_t line,
                                void (*test)(const std::string&), PerLab which = PerLab::Every,
                                Gl43Tag gl43 = Gl43Tag::Where4_3) {
    return register_per_lab(name, tags, test, which, gl43, file, line);
}
}  // namespace gsv::test
