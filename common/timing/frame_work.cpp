#include "common/timing/frame_work.h"

#include "common/core/error.h"
#include "common/core/number_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <utility>

namespace gsv {

const char* work_kind_name(WorkKind kind) {
    switch (kind) {
    case WorkKind::Fetch: return "fetch";
    case WorkKind::StorageBytes: return "storage";
    case WorkKind::Fragments: return "fragments";
    case WorkKind::Flops: return "flops";
    case WorkKind::Triangles: return "triangles";
    }
    return "?";
}

const char* shader_path_name(ShaderPath path) { return path == ShaderPath::Compute ? "compute" : "fragment"; }

std::string pair_ceiling_key(const std::string& flow_texture, const std::string& input_texture, ShaderPath path) {
    return "fetch " + flow_texture + " + " + input_texture + " " + shader_path_name(path);
}

std::string WorkItem::ceiling_key() const {
    switch (kind) {
    case WorkKind::Fetch: return "fetch " + texture + " " + shader_path_name(path);
    case WorkKind::StorageBytes: return std::string("storage ") + shader_path_name(path);
    case WorkKind::Fragments: return "fragments";
    case WorkKind::Flops: return std::string("flops ") + shader_path_name(path);
    case WorkKind::Triangles: return "triangles";
    }
    return "?";
}

std::string WorkItem::unit() const {
    switch (kind) {
    case WorkKind::Fetch: return "fetches";
    case WorkKind::StorageBytes: return "bytes";
    case WorkKind::Fragments: return "fragments";
    case WorkKind::Flops: return "flops";
    case WorkKind::Triangles: return "triangles";
    }
    return "?";
}

namespace {

// 106.0 M, 2.1 G: counts as people read them.
std::string scaled(double value) {
    const char* suffix = "";
    if (value >= 1e9) value /= 1e9, suffix = " G";
    else if (value >= 1e6) value /= 1e6, suffix = " M";
    else if (value >= 1e3) value /= 1e3, suffix = " k";
    char text[48];
    std::snprintf(text, sizeof text, "%.4g%s", value, suffix);
    return text;
}

}  // namespace

std::string FrameWork::describe(const std::string& indent) const {
    std::string out;
    for (const auto& item : items)
        out += indent + scaled(item.amount) + " " + item.unit() + " (" + item.ceiling_key() + "): " + item.what + "\n";
    if (upper_bound) out += indent + "(at most: every pixel covered, every loop at its full length; a streamline or ray that ends early does less)\n";
    return out;
}

std::string FrameWork::summary() const {
    std::string out;
    for (const auto& item : items) {
        std::string amount = scaled(item.amount);
        amount.erase(std::remove(amount.begin(), amount.end(), ' '), amount.end());
        out += (out.empty() ? "" : " + ") + amount + " " + item.ceiling_key();
    }
    return upper_bound && !out.empty() ? "<= " + out : out;
}

const Ceiling* Ceilings::find(const std::string& key) const {
    for (const auto& c : rates)
        if (c.key == key) return &c;
    return nullptr;
}

Json Ceilings::to_json() const {
    Json out = Json::object();
    out["renderer"] = renderer;
    Json list = Json::array();
    for (const auto& c : rates) {
        Json entry = Json::object();
        entry["key"] = c.key;
        entry["rate"] = c.rate;
        entry["low"] = c.low;
        entry["high"] = c.high;
        entry["unit"] = c.unit;
        if (!c.runs.empty()) {
            Json runs = Json::array();
            for (double r : c.runs) runs.push_back(r);
            entry["runs"] = runs;
        }
        list.push_back(entry);
    }
    out["ceilings"] = list;
    return out;
}

Ceilings Ceilings::from_json(const Json& json) {
    Ceilings out;
    out.renderer = json.string_at("renderer");
    const Json& list = json.array_at("ceilings");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const Json& entry = list.at(i);
        Ceiling c{entry.string_at("key"), entry.number_at("rate"), entry.number_at("low"), entry.number_at("high"),
                  entry.string_at("unit")};
        if (!(c.rate > 0) || !std::isfinite(c.rate))
            throw Error(json.source_name() + ": ceiling '" + c.key + "' has rate " + format_number(c.rate, 6) +
                        ": a measured rate is above 0");
        // Written by gsv-ceilings --runs N; a file of one run (or an older one) has none.
        if (entry.contains("runs")) {
            const Json& runs = entry.array_at("runs");
            for (std::size_t r = 0; r < runs.size(); ++r) {
                c.runs.push_back(runs.at(r).as_number());
                if (!(c.runs.back() > 0) || !std::isfinite(c.runs.back()))
                    throw Error(json.source_name() + ": ceiling '" + c.key + "' has run " + std::to_string(r + 1) +
                                " at " + format_number(c.runs.back(), 6) + ": a measured rate is above 0");
            }
        }
        out.rates.push_back(c);
    }
    return out;
}

Ceilings read_ceilings(const std::filesystem::path& path) { return Ceilings::from_json(read_json_file(path)); }

void write_ceilings(const std::filesystem::path& path, const Ceilings& ceilings) {
    std::ofstream out(path);
    if (!out || !(out << ceilings.to_json().dump(2) << "\n")) throw Error("cannot write '" + path.string() + "'");
}

std::optional<Ceilings> cached_ceilings(const std::filesystem::path& executable, const std::string& renderer) {
    std::filesystem::path path;
    if (const char* env = std::getenv("GSV_CEILINGS"); env && *env) path = env;
    else path = executable.parent_path().parent_path() / "ceilings.json";
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
    Ceilings ceilings = read_ceilings(path);
    if (ceilings.renderer != renderer) return std::nullopt;
    return ceilings;
}

std::string Roofline::describe(double measured_ms) const {
    char text[160];
    std::snprintf(text, sizeof text, "%s%.0f%% of this device's %s ceiling", upper_bound ? "at most " : "",
                  100.0 * fraction(measured_ms), limiter.c_str());
    return text;
}

std::string WorkItem::resource() const {
    return kind == WorkKind::Fetch ? std::string("texture (") + shader_path_name(path) + ")" : ceiling_key();
}

std::optional<Roofline> roofline(const FrameWork& work, const Ceilings& ceilings) {
    // Each resource's time: its items' amounts at their ceilings, added (lookups of two formats share the texture
    // units: LIC's flow and noise lookups take their turns); the frame's bound is the slowest resource.
    struct Resource {
        std::string name;
        double ms = 0, median_ms = 0;
        std::vector<const WorkItem*> fetches;  // the lookups it adds up, for a pair's ceiling
    };
    std::vector<Resource> resources;
    Roofline out;
    for (const auto& item : work.items) {
        const Ceiling* ceiling = ceilings.find(item.ceiling_key());
        if (!ceiling) {
            out.unmeasured.push_back(item.ceiling_key());
            continue;
        }
        const double median_ms = 1000.0 * item.amount / ceiling->rate;
        const double ms = 1000.0 * item.amount / ceiling->fastest();
        const std::string name = item.resource();
        auto found = std::find_if(resources.begin(), resources.end(), [&](const Resource& r) { return r.name == name; });
        if (found == resources.end()) found = resources.insert(resources.end(), Resource{name, 0, 0, {}});
        found->ms += ms;
        found->median_ms += median_ms;
        if (item.kind == WorkKind::Fetch) found->fetches.push_back(&item);
    }
    if (resources.empty()) return std::nullopt;
    // Two formats looked up in turn (LIC's flow and input) can run faster than each one's benchmark alone allows;
    // where their pair was measured too (gsv-ceilings' fetch_pair.frag), the faster of the two ceilings holds.
    for (Resource& r : resources) {
        if (r.fetches.size() != 2 || r.fetches[0]->texture == r.fetches[1]->texture) continue;
        for (const auto& [a, b] : {std::pair{r.fetches[0], r.fetches[1]}, std::pair{r.fetches[1], r.fetches[0]}}) {
            const Ceiling* pair = ceilings.find(pair_ceiling_key(a->texture, b->texture, a->path));
            if (!pair) continue;
            const double amount = a->amount + b->amount;
            r.ms = std::min(r.ms, 1000.0 * amount / pair->fastest());
            r.median_ms = std::min(r.median_ms, 1000.0 * amount / pair->rate);
        }
    }
    out.upper_bound = work.upper_bound;
    for (const Resource& r : resources) {
        if (r.ms > out.bound_ms) out.bound_ms = r.ms, out.limiter = r.name;
        out.median_bound_ms = std::max(out.median_bound_ms, r.median_ms);
    }
    return out;
}

void check_within_ceiling(const Roofline& bound, double measured_ms, const std::string& what) {
    if (measured_ms < bound.bound_ms)
        throw Error(what + ": " + format_number(measured_ms, 4) + " ms a frame is faster than this device's " + bound.limiter +
                    " ceiling allows (" + format_number(bound.bound_ms, 4) + " ms at its fastest, fraction " +
                    format_number(bound.fraction(measured_ms), 3) +
                    "): the timing did not wait for the device, or the work is overstated");
}

}  // namespace gsv
