// Shards of a batch without grading anything: which names each shard takes, K/N parsing, rosters, and what
// merge refuses, on hand-written batch records (tests/batch_shards.sh grades real submissions).
#include "catch.hpp"
#include "test_support.h"

#include "common/core/error.h"
#include "grader/src/batch/batch.h"
#include "grader/src/batch/batch_merge.h"
#include "grader/src/batch/batch_record.h"

#include <algorithm>
#include <functional>
#include <set>

using namespace gsv;

namespace {

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "<no error>";
}

// The record a shard of `roster` would leave, with every student graded `score` of 10.
BatchRecord shard_record(const std::vector<std::string>& roster, int k, int n, double score) {
    BatchRecord r;
    r.seed = 4711;
    r.shard = k;
    r.shard_count = n;
    r.kit = "0123456789abcdef";
    r.options = {"--labs", "lab01", "--no-timing"};
    r.roster = roster;
    std::sort(r.roster.begin(), r.roster.end());
    for (const std::string& name : shard_names(roster, k, n)) {
        BatchEntry e;
        e.name = name;
        e.graded = true;
        e.score = score;
        e.max_score = 10;
        r.entries.push_back(e);
    }
    return r;
}

}  // namespace

TEST_CASE("batch: the shards of a class are disjoint, cover it, and do not depend on the order given", "[unit][batch]") {
    const std::vector<std::string> roster{"zoe", "ada", "mia", "bob", "eve", "cy", "dan"};
    std::vector<std::string> reversed(roster.rbegin(), roster.rend());
    for (int n : {1, 2, 3, 7, 10}) {
        std::multiset<std::string> seen;
        for (int k = 1; k <= n; ++k) {
            const auto names = shard_names(roster, k, n);
            CHECK(names == shard_names(reversed, k, n));
            CHECK(std::is_sorted(names.begin(), names.end()));
            seen.insert(names.begin(), names.end());
        }
        CHECK(seen == std::multiset<std::string>(roster.begin(), roster.end()));
    }
    CHECK(shard_names(roster, 2, 3) == std::vector<std::string>{"bob", "eve"});  // ada bob cy dan eve mia zoe
    CHECK(shard_names(roster, 10, 10).empty());
}

TEST_CASE("batch: K/N is checked, with one line naming the value", "[unit][batch]") {
    CHECK(parse_shard("3/8") == std::pair{3, 8});
    CHECK(parse_shard("1/1") == std::pair{1, 1});
    for (const char* bad : {"0/3", "4/3", "3", "a/b", "1/0", "-1/3", " 1/3", "1/3/4", ""}) {
        const std::string e = error_of([&] { parse_shard(bad); });
        INFO(bad << ": " << e);
        CHECK(e.find("--shard") != std::string::npos);
        CHECK(e.find('\n') == std::string::npos);
    }
}

TEST_CASE("batch: a roster skips blanks and comments and refuses names that would leave the output folder", "[unit][batch]") {
    test::TempDir dir;
    CHECK(read_roster(dir.write("r.txt", "# the class\n ada \n\nbob\n")) == std::vector<std::string>{"ada", "bob"});
    CHECK(error_of([&] { read_roster(dir.write("bad.txt", "ada\n../x\n")); }).find("bad.txt:2: '../x'") != std::string::npos);
    CHECK(error_of([&] { read_roster(dir.write("q.txt", "a\"b\n")); }).find("q.txt:1:") != std::string::npos);
    CHECK(error_of([&] { read_roster(dir.write("empty.txt", "# nobody\n")); }).find("names no submissions") != std::string::npos);
    CHECK(error_of([&] { read_roster(dir.path("missing.txt")); }).find("missing.txt") != std::string::npos);
}

TEST_CASE("batch: merge joins records in class order and refuses shards that were not graded alike", "[unit][batch]") {
    test::TempDir dir;
    const std::vector<std::string> roster{"ada", "bob", "cy", "dan", "eve"};
    auto shard = [&](const std::string& folder, const BatchRecord& r) {
        std::filesystem::create_directories(dir.path(folder));
        write_batch_record(r, dir.path(folder));
        for (const auto& e : r.entries) dir.write(folder + "/" + e.name + "/results.json", "{}");
        return dir.path(folder);
    };
    const auto s1 = shard("s1", shard_record(roster, 1, 2, 7));
    const auto s2 = shard("s2", shard_record(roster, 2, 2, 7));
    const BatchRecord merged = merge_shards({s2, s1}, dir.path("merged"));
    REQUIRE(merged.entries.size() == roster.size());
    for (std::size_t i = 0; i < roster.size(); ++i) CHECK(merged.entries[i].name == roster[i]);
    CHECK(read_batch_record(dir.path("merged")).entries.size() == roster.size());
    CHECK(std::filesystem::exists(dir.path("merged/eve/results.json")));

    BatchRecord other_seed = shard_record(roster, 2, 2, 7);
    other_seed.seed = 4712;
    CHECK(error_of([&] { merge_shards({s1, shard("seed", other_seed)}, dir.path("m1")); }).find("different seeds") != std::string::npos);
    BatchRecord other_kit = shard_record(roster, 2, 2, 7);
    other_kit.kit = "fedcba9876543210";
    CHECK(error_of([&] { merge_shards({s1, shard("kit", other_kit)}, dir.path("m2")); }).find("different kits") != std::string::npos);
    BatchRecord other_labs = shard_record(roster, 2, 2, 7);
    other_labs.options = {"--labs", "lab02", "--no-timing"};
    CHECK(error_of([&] { merge_shards({s1, shard("labs", other_labs)}, dir.path("m3")); }).find("different labs (lab01; lab02)") != std::string::npos);
    BatchRecord other_options = shard_record(roster, 2, 2, 7);
    other_options.options = {"--labs", "lab01"};
    CHECK(error_of([&] { merge_shards({s1, shard("options", other_options)}, dir.path("m4")); }).find("different options") != std::string::npos);
    CHECK(error_of([&] { merge_shards({s1, shard("three", shard_record(roster, 2, 3, 7))}, dir.path("m5")); }).find("split the class differently") != std::string::npos);
    CHECK(error_of([&] { merge_shards({s1}, dir.path("m6")); }).find("shard 2/2 missing, so are the students bob, dan") != std::string::npos);
    CHECK(error_of([&] { merge_shards({s1, s1, s2}, dir.path("m7")); }).find("both shard 1/2") != std::string::npos);
    BatchRecord stray = shard_record(roster, 2, 2, 7);
    stray.entries.pop_back();
    CHECK(error_of([&] { merge_shards({s1, shard("stray", stray)}, dir.path("m8")); }).find("does not hold that shard's students") != std::string::npos);
    CHECK(error_of([&] { merge_shards({s1, s2}, dir.path("merged")); }).find("new or empty") != std::string::npos);
    for (const char* m : {"m1", "m2", "m3", "m4", "m5", "m6", "m7", "m8"}) CHECK_FALSE(std::filesystem::exists(dir.path(m)));
}

TEST_CASE("batch: the kit fingerprint follows what grades and ignores where the kit is", "[unit][batch]") {
    test::TempDir dir;
    for (const char* kit : {"a", "b"}) {
        dir.write(std::string(kit) + "/grader/cases/lab01.json", "{\"cases\": []}");
        dir.write(std::string(kit) + "/solutions/lab01_x/lab.cpp", "int x;");
    }
    CHECK(kit_fingerprint(dir.path("a")) == kit_fingerprint(dir.path("b")));
    dir.write("b/solutions/lab01_x/lab.cpp", "int y;");
    CHECK(kit_fingerprint(dir.path("a")) != kit_fingerprint(dir.path("b")));
    // A file moved is another kit, even with the same bytes.
    dir.write("c/grader/cases/lab01.json", "{\"cases\": []}");
    dir.write("c/solutions/lab01_y/lab.cpp", "int x;");
    CHECK(kit_fingerprint(dir.path("a")) != kit_fingerprint(dir.path("c")));
    CHECK(error_of([&] { kit_fingerprint(dir.path("nowhere")); }).find("is not a kit") != std::string::npos);
}
