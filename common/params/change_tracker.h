#pragma once
// What a lab builds from its parameters (a texture, a mesh, particle buffers) is remade only when something it
// was made from has changed. What it was made from is recorded, not listed: every parameter the building read
// (through a getter, as an active uniform of a program it used, or compiled into that program), plus the keys
// handed in for what is not a parameter (the frame's size, a file's time, another tracker's version). A parameter
// cannot be left out of a list that nobody writes.
//
//   gsv::Tracked<gsv::Texture> flow_;
//   flow_.update(kit.params(), [&] { return make_flow_texture(kit, frame); }, frame.width, frame.height);
//   flow_->bind(1);
#include "common/params/params.h"

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <type_traits>
#include <string>
#include <utility>
#include <vector>

namespace gsv {

class ChangeTracker {
public:
    // Runs `build` when nothing has been built yet, or a parameter it read last time or one of `keys` has changed
    // since; returns whether it ran. A build that throws leaves nothing built, so the next call tries again.
    // Called inside another tracker's build, it reports what it read to that one too.
    template <class Build, class... Keys>
    bool run_if_changed(const Params& params, Build&& build, const Keys&... keys) {
        std::vector<std::string> key_texts{key_text(keys)...};
        if (built_ && key_texts == keys_ && !read_changed(params)) {
            params.note_reads(read_indices());
            return false;
        }
        built_ = false;
        std::vector<std::size_t> log;
        std::vector<std::size_t>* outer = params.swap_read_log(&log);
        try {
            build();
        } catch (...) {
            params.swap_read_log(outer);
            throw;
        }
        params.swap_read_log(outer);
        remember(params, log);
        params.note_reads(read_indices());
        keys_ = std::move(key_texts);
        built_ = true;
        ++version_;
        return true;
    }

    // Counts the builds: a key for what is built from this one's result.
    std::uint64_t version() const { return version_; }
    // The next run_if_changed builds whatever changed (used when the built thing was changed by other means).
    void invalidate() { built_ = false; }
    // The parameters the last build read, by index: for tests and messages.
    std::vector<std::size_t> read_indices() const {
        std::vector<std::size_t> indices;
        for (const auto& r : reads_) indices.push_back(r.first);
        return indices;
    }

private:
    template <class Key>
    static std::string key_text(const Key& key) {
        std::ostringstream out;
        out.precision(17);
        if constexpr (std::is_integral_v<Key> && sizeof(Key) > sizeof(std::uint64_t)) {
            // libc++ (Emscripten's) counts file times in __int128, which a stream cannot print: as its two halves.
            out << static_cast<std::uint64_t>(key >> 64) << ':' << static_cast<std::uint64_t>(key);
        } else {
            out << key;
        }
        return out.str();
    }
    bool read_changed(const Params& params) const {
        for (const auto& [index, text] : reads_)
            if (params.text_at(index) != text) return true;
        return false;
    }
    void remember(const Params& params, std::vector<std::size_t> log) {
        std::sort(log.begin(), log.end());
        log.erase(std::unique(log.begin(), log.end()), log.end());
        reads_.clear();
        for (std::size_t index : log) reads_.emplace_back(index, params.text_at(index));
    }

    bool built_ = false;
    std::uint64_t version_ = 0;
    std::vector<std::string> keys_;
    std::vector<std::pair<std::size_t, std::string>> reads_;
};

// A value kept with the tracker that says when to remake it.
template <class T>
class Tracked {
public:
    // Remakes the value with make() (which returns a T) when what it was made from changed; returns whether it did.
    template <class Make, class... Keys>
    bool update(const Params& params, Make&& make, const Keys&... keys) {
        return tracker_.run_if_changed(params, [&] { value_ = make(); }, keys...);
    }
    const T& operator*() const { return value_; }
    T& operator*() { return value_; }
    const T* operator->() const { return &value_; }
    T* operator->() { return &value_; }
    std::uint64_t version() const { return tracker_.version(); }
    void invalidate() { tracker_.invalidate(); }
    const ChangeTracker& tracker() const { return tracker_; }

private:
    ChangeTracker tracker_;
    T value_{};
};

}  // namespace gsv
