// Live references kept on disk across runs (grader/src/run/reference_store.h): an entry gives back what was stored,
// a damaged one is never trusted, the key changes with everything a render depends on, and a rerun grades case for
// case as a first run does.
#include "catch.hpp"
#include "grader_fixture.h"
#include "test_support.h"

#include "common/io/json.h"
#include "grader/src/grade/grade.h"
#include "grader/src/run/reference_store.h"

#include <cstdlib>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace gsv;

namespace {

LabRun passed_run(int seed) {
    LabRun run;
    run.status = CaseStatus::Passed;
    run.detail = "";
    run.renderer = "llvmpipe (LLVM 15.0.6, 256 bits)";
    Image image;
    image.width = 5;
    image.height = 3;
    image.rgba.resize(5 * 3 * 4);
    for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = static_cast<std::uint8_t>(i * 7 + seed);
    run.image = image;
    DataArray positions{"positions", 4, {}};
    for (int i = 0; i < 40; ++i) positions.values.push_back(0.25f * float(i) - float(seed));
    run.arrays.push_back(positions);
    return run;
}

std::vector<fs::path> entries(const fs::path& folder) {
    std::vector<fs::path> files;
    if (fs::is_directory(folder))
        for (const auto& e : fs::directory_iterator(folder)) files.push_back(e.path());
    return files;
}

std::string read_all(const fs::path& file) { return test::read_text(file); }

void write_all(const fs::path& file, const std::string& bytes) { std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes; }

}  // namespace

TEST_CASE("reference store: what is stored comes back byte for byte, under its own key only", "[unit][references]") {
    test::TempDir dir;
    ReferenceStore store(dir.path("refs"));
    const LabRun run = passed_run(1);
    CHECK_FALSE(store.load("key a"));
    store.store("key a", run);
    CHECK(store.stored() == 1);
    const auto back = store.load("key a");
    REQUIRE(back);
    CHECK(back->status == CaseStatus::Passed);
    CHECK(back->renderer == run.renderer);
    REQUIRE(back->image);
    CHECK(back->image->width == 5);
    CHECK(back->image->height == 3);
    CHECK(back->image->rgba == run.image->rgba);
    REQUIRE(back->arrays.size() == 1);
    CHECK(back->arrays[0].name == "positions");
    CHECK(back->arrays[0].components == 4);
    CHECK(back->arrays[0].values == run.arrays[0].values);
    CHECK(store.hits() == 1);
    CHECK_FALSE(store.load("key b"));
    CHECK(store.problem().empty());

    // A failed render is never stored.
    LabRun crashed = run;
    crashed.status = CaseStatus::Crash;
    store.store("key c", crashed);
    CHECK_FALSE(store.load("key c"));
    CHECK(store.stored() == 1);
}

TEST_CASE("reference store: a damaged, cut or swapped entry is removed and not trusted, in one line", "[unit][references]") {
    test::TempDir dir;
    const fs::path folder = dir.path("refs");
    SECTION("one byte of the image changed") {
        ReferenceStore store(folder);
        store.store("key a", passed_run(1));
        const fs::path file = entries(folder).at(0);
        std::string bytes = read_all(file);
        bytes[bytes.size() / 2] ^= 0x01;
        write_all(file, bytes);
        CHECK_FALSE(store.load("key a"));
        CHECK(store.damaged() == 1);
        CHECK(store.problem().find("does not match its checksum: removed, and the case rendered") != std::string::npos);
        CHECK_FALSE(fs::exists(file));
    }
    SECTION("cut short") {
        ReferenceStore store(folder);
        store.store("key a", passed_run(1));
        const fs::path file = entries(folder).at(0);
        const std::string bytes = read_all(file);
        write_all(file, bytes.substr(0, bytes.size() - 40));
        CHECK_FALSE(store.load("key a"));
        CHECK(store.damaged() == 1);
        CHECK_FALSE(fs::exists(file));
    }
    SECTION("another key's entry under this key's name") {
        ReferenceStore store(folder);
        store.store("key a", passed_run(1));
        const fs::path a = entries(folder).at(0);
        store.store("key b", passed_run(2));
        fs::path b;
        for (const auto& f : entries(folder))
            if (f != a) b = f;
        REQUIRE(!b.empty());
        fs::copy_file(a, b, fs::copy_options::overwrite_existing);
        CHECK_FALSE(store.load("key b"));
        CHECK(store.problem().find("holds another case's key") != std::string::npos);
        CHECK(store.load("key a"));
    }
    SECTION("a link or a folder where an entry should be") {
        ReferenceStore store(folder);
        store.store("key a", passed_run(1));
        const fs::path file = entries(folder).at(0);
        fs::remove(file);
        fs::create_symlink(dir.write("elsewhere", "x"), file);
        CHECK_FALSE(store.load("key a"));
        CHECK(store.problem().find("is not a plain file") != std::string::npos);
        CHECK_FALSE(fs::exists(fs::symlink_status(file)));
    }
    SECTION("not an entry at all") {
        ReferenceStore store(folder);
        store.store("key a", passed_run(1));
        write_all(entries(folder).at(0), "hello");
        CHECK_FALSE(store.load("key a"));
        CHECK(store.problem().find("is not an entry") != std::string::npos);
    }
}

TEST_CASE("reference store: a folder that cannot be written is one line, and nothing is stored", "[unit][references]") {
    test::TempDir dir;
    const fs::path file = dir.write("refs", "a file where the folder should be");
    ReferenceStore store(file);
    store.store("key a", passed_run(1));
    CHECK(store.stored() == 0);
    CHECK(store.problem().find("cannot store references in " + file.string()) != std::string::npos);
    CHECK_FALSE(store.load("key a"));
    CHECK(read_all(file) == "a file where the folder should be");
}

TEST_CASE("reference store: the key's context changes with any file of the kit and with the driver's environment", "[unit][references]") {
    test::TempDir dir;
    dir.write("kit/shaders/a.glsl", "void main() {}\n");
    dir.write("kit/data/field.raw", "0123");
    const std::string first = reference_context(dir.path("kit"));
    CHECK(reference_context(dir.path("kit")) == first);
    dir.write("kit/data/field.raw", "0124");
    const std::string edited = reference_context(dir.path("kit"));
    CHECK(edited != first);
    const char* old = std::getenv("GALLIUM_DRIVER");
    const std::string kept = old ? old : "";
    setenv("GALLIUM_DRIVER", "softpipe-for-this-test", 1);
    const std::string softpipe = reference_context(dir.path("kit"));
    if (old) setenv("GALLIUM_DRIVER", kept.c_str(), 1); else unsetenv("GALLIUM_DRIVER");
    CHECK(softpipe != edited);
    CHECK(softpipe.find("GALLIUM_DRIVER=softpipe-for-this-test") != std::string::npos);
    CHECK(reference_context(dir.path("kit")) == edited);
}

TEST_CASE("grader: live references from the store grade case for case as rendered ones, and a damaged one is rendered again", "[grader][references]") {
    test::TempDir dir;
    const auto options_for = [&](const std::string& out) {
        GradeOptions options = test::instructor_options("lab01", dir.path(out));
        options.cases = {"gooch", "phong"};
        options.timing = false;
        options.hidden = false;
        options.allow_readable_kit = false;
        options.reference_store = dir.path("refs");
        return options;
    };
    const GradeReport first = grade(options_for("out1"));
    INFO(first.references);
    if (first.references.find("none kept on disk") != std::string::npos) {
        WARN("the walls cannot go up here: live references are not kept, so the store is not used");
        return;
    }
    CHECK(first.references.rfind("2 rendered, 0 from the store (", 0) == 0);
    REQUIRE(entries(dir.path("refs")).size() == 2);

    const auto same_grades = [&](const GradeReport& a, const GradeReport& b) {
        REQUIRE(a.results.size() == b.results.size());
        for (std::size_t i = 0; i < a.results.size(); ++i) {
            INFO(a.results[i].name);
            CHECK(a.results[i].status == b.results[i].status);
            CHECK(a.results[i].points == b.results[i].points);
            CHECK(a.results[i].detail == b.results[i].detail);
            CHECK(test::read_text(dir.path("out1") / a.results[i].expected_png) ==
                  test::read_text(dir.path("out2") / b.results[i].expected_png));
        }
    };
    const GradeReport rerun = grade(options_for("out2"));
    INFO(rerun.references);
    CHECK(rerun.references.rfind("0 rendered, 2 from the store (", 0) == 0);
    same_grades(first, rerun);

    // One byte of one entry changed: that case is rendered again, the report says so, the grades do not change.
    const fs::path damaged = entries(dir.path("refs")).at(0);
    std::string bytes = read_all(damaged);
    bytes[bytes.size() / 3] ^= 0x10;
    write_all(damaged, bytes);
    const GradeReport after = grade(options_for("out3"));
    INFO(after.references);
    CHECK(after.references.rfind("1 rendered, 1 from the store (", 0) == 0);
    CHECK(after.references.find("does not match its checksum") != std::string::npos);
    same_grades(first, after);

    // --fresh-references renders both again.
    GradeOptions fresh = options_for("out4");
    fresh.stored_references = false;
    const GradeReport fresh_report = grade(fresh);
    CHECK(fresh_report.references.rfind("2 rendered, 0 from the store (", 0) == 0);
    same_grades(first, fresh_report);
}

TEST_CASE("reference store: a folder or an entry another user could change is never trusted", "[unit][references]") {
    test::TempDir dir;
    const fs::path folder = dir.path("private") / "refs";
    // Made when missing, 0755 whatever the umask, and then no one else can write it or a folder above it.
    CHECK(writable_by_others(folder) == "");
    CHECK((fs::status(folder).permissions() & (fs::perms::group_write | fs::perms::others_write)) == fs::perms::none);
    // A folder on the path that others may write (without the sticky bit /tmp has) is named.
    fs::permissions(dir.path("private"), fs::perms::others_write, fs::perm_options::add);
    CHECK(writable_by_others(folder) == dir.path("private").string() + " is writable by its group or by others");
    fs::permissions(dir.path("private"), fs::perms::others_write, fs::perm_options::remove);
    // Reached through a link: the link's folder and the folder it leads to are both looked at.
    fs::create_directories(dir.path("open"));
    fs::permissions(dir.path("open"), fs::perms::all);
    fs::create_directory_symlink(dir.path("private"), dir.path("open") / "link");
    CHECK(writable_by_others(dir.path("open") / "link" / "refs") == dir.path("open").string() + " is writable by its group or by others");
    fs::create_directory_symlink(dir.path("open"), dir.path("to-open"));
    fs::create_directories(dir.path("open") / "refs");
    CHECK(writable_by_others(dir.path("to-open") / "refs").find("open is writable by its group or by others") != std::string::npos);

    // Entries are written 0644 whatever the umask, and one that others may write is removed, not read.
    ReferenceStore store(folder);
    const mode_t old_mask = umask(0);
    store.store("key a", passed_run(1));
    umask(old_mask);
    const fs::path file = entries(folder).at(0);
    CHECK((fs::status(file).permissions() & (fs::perms::group_write | fs::perms::others_write)) == fs::perms::none);
    REQUIRE(store.load("key a"));
    fs::permissions(file, fs::perms::others_write, fs::perm_options::add);
    CHECK_FALSE(store.load("key a"));
    CHECK(store.problem().find("could have been changed by another user: removed, and the case rendered") != std::string::npos);
    CHECK_FALSE(fs::exists(file));
    // A second name for an entry (a hard link made by whoever could) is not trusted either.
    store.store("key a", passed_run(1));
    fs::create_hard_link(entries(folder).at(0), dir.path("private") / "second-name");
    CHECK_FALSE(store.load("key a"));
}

TEST_CASE("grader: where the walls are down, a root grader keeps live references where student code cannot write them",
          "[grader][references]") {
    if (geteuid() != 0) {
        WARN("not root: student code runs as the grader's own uid where the walls are down, so no store is kept there");
        return;
    }
    test::TempDir dir;
    const auto options_for = [&](const std::string& out) {
        GradeOptions options = test::instructor_options("lab01", dir.path(out));
        options.cases = {"gooch"};
        options.timing = false;
        options.hidden = false;
        options.namespaces = false;  // Docker's default seccomp profile, and Gradescope's containers
        options.allow_readable_kit = true;
        options.reference_store = dir.path("refs");
        return options;
    };
    const GradeReport first = grade(options_for("out1"));
    INFO(first.sandbox << "\n" << first.references);
    CHECK(first.references.rfind("1 rendered, 0 from the store (", 0) == 0);
    const GradeReport rerun = grade(options_for("out2"));
    INFO(rerun.references);
    CHECK(rerun.references.rfind("0 rendered, 1 from the store (", 0) == 0);
    REQUIRE(rerun.results.size() == first.results.size());
    CHECK(rerun.results.at(0).status == first.results.at(0).status);
    // A store that the leased uid could write is not used at all, and the report says why.
    fs::permissions(dir.path("refs"), fs::perms::others_write, fs::perm_options::add);
    const GradeReport open = grade(options_for("out3"));
    INFO(open.references);
    CHECK(open.references.rfind("rendered in this run; none kept on disk, where student code could change them: ", 0) == 0);
    CHECK(open.references.find("refs is writable by its group or by others") != std::string::npos);
}
