#pragma once
// An array a case checks, as every floor speaks of it: its tolerance (a case file's), what it is compared with (the live
// reference's whole array or a golden's sample: grader/src/golden/array_golden.h) and how it differed
// (grader/src/judge/array_compare.h compares).
#include "common/io/data_array.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gsv {

struct ArrayTolerance {
    double max_abs = 0;                 // an element differs when any component is off by more
    double max_differing_fraction = 0;  // of the elements compared, allowed to differ
};

// What an array is compared with: the live reference's whole array, or a golden's sample of it
// (grader/src/golden/array_golden.h).
struct ExpectedArray {
    std::string name;
    std::size_t count = 0;               // elements of the whole array
    int components = 4;
    std::vector<std::uint32_t> indices;  // the elements held, ascending; empty: every element, in order
    std::vector<float> values;           // the held elements' components, element-major

    std::size_t held() const { return indices.empty() ? count : indices.size(); }
    std::size_t element(std::size_t k) const { return indices.empty() ? k : indices[k]; }
};

// The whole array, as a live reference hands it in.
ExpectedArray expected_from(const DataArray& array);

struct ArrayDiff {
    std::string name;
    ArrayTolerance tolerance;
    // Set when nothing could be compared: no such array handed in, or another count or number of components.
    std::string problem;
    std::size_t count = 0;       // elements of the reference's array
    int components = 0;
    std::size_t compared = 0;    // elements compared: all, or a golden's sample
    std::size_t differing = 0;
    std::size_t non_finite = 0;  // differing elements with NaN or Inf where the reference is finite
    double max_abs_diff = 0;     // over components finite on both sides
    std::size_t first = 0;       // element index of the first difference, when any differs
    std::vector<float> first_actual, first_expected;

    // No problem, and differing <= floor(max_differing_fraction * compared).
    bool within() const;
    // One line, e.g. "positions: 1,234 of 65,536 elements (1.9%) differ by more than 0.0001; first at element 17:
    // (0.1, 0.2, 0.3, 1) where the reference has (0.1, 0.25, 0.3, 1)"; the problem when there is one.
    std::string summary() const;
};

// 65536 -> "65,536": counts a person reads at a glance.
std::string with_commas(std::size_t n);

}  // namespace gsv
