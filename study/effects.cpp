#include "study/effects.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <utility>

namespace vssw::study {
namespace {

using Key = std::vector<std::uint32_t>;  // metric, engine, settings, then the other varied parameters' levels

// The keys under which a row pairs: its own levels of the other varied parameters, one key per level of each that does
// not apply to it.
std::vector<Key> pairing_keys(const StudyData& d, const StudyRow& row, const std::vector<std::size_t>& others) {
    std::vector<Key> keys = {{row.metric, row.levels.front(), row.levels.back()}};
    for (std::size_t c : others) {
        const std::uint32_t level = row.levels[c];
        if (level != kEmptyLevel) {
            for (Key& k : keys) k.push_back(level);
            continue;
        }
        std::vector<Key> expanded;
        for (const Key& k : keys)
            for (std::uint32_t l : d.columns[c].order) {
                expanded.push_back(k);
                expanded.back().push_back(l);
            }
        keys = std::move(expanded);
    }
    return keys;
}

// Accumulates one (parameter level, metric)'s pairs.
struct Tally {
    std::vector<double> changes;
    long pairs = 0, up = 0, down = 0;
};

void add_pair(Tally& t, bool binary, double base, double other) {
    if (!std::isfinite(base) || !std::isfinite(other)) return;
    if (binary) {
        ++t.pairs;
        t.up += base == 0.0 && other == 1.0 ? 1 : 0;
        t.down += base == 1.0 && other == 0.0 ? 1 : 0;
    } else if (base != 0.0) {
        ++t.pairs;
        t.changes.push_back(other / base - 1.0);
    }
}

Effect effect_of(const StudyData& d, std::size_t column, std::uint32_t level, std::size_t metric, const Tally& t) {
    const ColumnLevels& c = d.columns[column];
    Effect e;
    e.column = column;
    e.parameter = c.key;
    e.from = c.texts[c.order.front()];
    e.to = c.texts[level];
    e.assumption = c.assumption;
    e.physical = c.physical;
    e.metric = metric;
    e.binary = d.metrics[metric].binary;
    e.pairs = t.pairs;
    e.up = t.up;
    e.down = t.down;
    const double n = static_cast<double>(t.pairs);
    if (t.pairs == 0) {
        e.median = e.lo = e.hi = std::nan("");
    } else if (e.binary) {
        e.median = static_cast<double>(t.up - t.down) / n;
        e.lo = -static_cast<double>(t.down) / n;
        e.hi = static_cast<double>(t.up) / n;
    } else {
        e.median = median(t.changes);
        e.lo = *std::min_element(t.changes.begin(), t.changes.end());
        e.hi = *std::max_element(t.changes.begin(), t.changes.end());
    }
    return e;
}

// The effects of one parameter: its rows grouped by pairing key, each group's first-level rows paired with its rows at
// every other level (each pair of rows once, however many keys they share). The groups are runs of one sorted list
// (keys laid out flat), not a map of maps: building those maps was a tenth of a closed-form study's time, and no
// result depends on the order the pairs come in (a median, a minimum and a maximum of each tally).
std::vector<Effect> effects_of(const StudyData& d, std::size_t column) {
    const ColumnLevels& col = d.columns[column];
    if (col.order.size() < 2) return {};  // varied in the file, but a single level applies (a parapet's hinge)
    std::vector<std::size_t> others;
    for (std::size_t c : d.varied())
        if (c != column) others.push_back(c);
    const std::size_t width = 3 + others.size();  // a Key's length (pairing_keys)
    std::vector<std::uint32_t> keys;               // each entry's key, `width` levels
    std::vector<std::pair<std::uint32_t, std::size_t>> entries;  // each entry's level of `column` and row
    for (std::size_t i = 0; i < d.rows.size(); ++i) {
        const std::uint32_t level = d.rows[i].levels[column];
        if (level == kEmptyLevel) continue;
        const StudyRow& row = d.rows[i];
        const auto applies = [&](std::size_t c) { return row.levels[c] != kEmptyLevel; };
        if (std::all_of(others.begin(), others.end(), applies)) {  // one key: written in place
            keys.insert(keys.end(), {row.metric, row.levels.front(), row.levels.back()});
            for (std::size_t c : others) keys.push_back(row.levels[c]);
            entries.push_back({level, i});
            continue;
        }
        for (const Key& k : pairing_keys(d, row, others)) {
            keys.insert(keys.end(), k.begin(), k.end());
            entries.push_back({level, i});
        }
    }
    const auto key_of = [&](std::size_t e) { return keys.begin() + static_cast<std::ptrdiff_t>(e * width); };
    const auto same_key = [&](std::size_t a, std::size_t b) { return std::equal(key_of(a), key_of(a) + width, key_of(b)); };
    std::vector<std::size_t> order(entries.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        if (!same_key(a, b)) return std::lexicographical_compare(key_of(a), key_of(a) + width, key_of(b), key_of(b) + width);
        return entries[a] < entries[b];
    });
    const std::uint32_t first = col.order.front();
    std::vector<std::pair<std::size_t, std::size_t>> pairs;  // (base row, other row), each once below
    for (std::size_t begin = 0, end = 0; begin < order.size(); begin = end) {
        end = begin + 1;
        while (end < order.size() && same_key(order[begin], order[end])) ++end;
        std::vector<std::size_t> base;  // the group's rows at the first level
        for (std::size_t g = begin; g < end; ++g)
            if (entries[order[g]].first == first) base.push_back(entries[order[g]].second);
        if (base.empty()) continue;
        for (std::size_t g = begin; g < end; ++g) {
            const auto [level, o] = entries[order[g]];
            if (level == first) continue;
            for (std::size_t b : base) pairs.push_back({b, o});
        }
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    std::map<std::pair<std::uint32_t, std::size_t>, Tally> tallies;  // (level, metric) -> pairs
    for (const auto& [b, o] : pairs) {
        const std::size_t metric = d.rows[b].metric;
        add_pair(tallies[{d.rows[o].levels[column], metric}], d.metrics[metric].binary, d.rows[b].value,
                 d.rows[o].value);
    }
    std::vector<Effect> out;
    for (std::size_t k = 1; k < col.order.size(); ++k)
        for (std::size_t m = 0; m < d.metrics.size(); ++m) {
            if (!d.metrics[m].any_value) continue;
            const auto it = tallies.find({col.order[k], m});
            out.push_back(effect_of(d, column, col.order[k], m, it == tallies.end() ? Tally{} : it->second));
        }
    return out;
}

}  // namespace

double Effect::magnitude() const {
    if (pairs == 0) return 0.0;
    return binary ? static_cast<double>(up + down) / static_cast<double>(pairs) : std::abs(median);
}

double Effect::extent() const { return pairs == 0 ? 0.0 : std::max(std::abs(lo), std::abs(hi)); }

double median(std::vector<double> values) {
    if (values.empty()) return std::nan("");
    const std::size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
    const double upper = values[mid];
    if (values.size() % 2 == 1) return upper;
    const double lower = *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid));
    return 0.5 * (lower + upper);
}

std::vector<Effect> parameter_effects(const StudyData& data) {
    std::vector<Effect> all;
    for (std::size_t c : data.varied())
        for (Effect& e : effects_of(data, c)) all.push_back(std::move(e));
    std::stable_sort(all.begin(), all.end(), [](const Effect& a, const Effect& b) {
        if (a.magnitude() != b.magnitude()) return a.magnitude() > b.magnitude();
        return a.extent() > b.extent();
    });
    return all;
}

}  // namespace vssw::study
