#pragma once
// What a sweep measures a lab against: the instructor's side of a lab, apart from the lab itself. A lab declares its
// accuracy knob (common/params/params.h) and draws; its sweep plan, in reference/<lab dir>/sweep_plan.cpp, says which
// settings the sweep's reference is drawn with, what it is called, and which yardsticks (reference/) measure each
// point. Only the solution targets link a plan (cmake/labs.cmake); a starter, a student's build and the grader's
// submission build sweep with the default: the knob's last value, rendered, and the table says it was not shown
// converged.
#include "common/image/image.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gsv {

class LabKit;
struct Frame;

using SweepMetrics = std::vector<std::pair<std::string, double>>;

class SweepPlan {
public:
    virtual ~SweepPlan() = default;
    // The settings of the reference a sweep measures error against; empty: the knob's last value.
    virtual std::vector<std::string> reference() const { return {}; }
    // That reference in words, for the table, the CSV and the slides ("LIC along the exact streamlines, in double
    // precision on the CPU"); empty: its settings, said to be the most accurate setting.
    virtual std::string reference_name() const { return {}; }
    // The next refinement of reference(), to show it converged: the sweep draws both and reports whether their
    // difference is below the smallest error it measured. Empty: exact, or no claim.
    virtual std::vector<std::string> refinement() const { return {}; }
    // True: each curve of the series is measured against the reference drawn with its own series value
    // (lab 06: an isosurface against an isosurface, not against DVR). False: one reference for all curves.
    virtual bool reference_per_series() const { return false; }
    // An exact reference image for the current settings, drawn by a yardstick (on the CPU, in double): the sweep's
    // error is then against it rather than against a rendered reference(). None: not available.
    virtual std::optional<Image> exact_image(LabKit&, const Frame&) { return std::nullopt; }
    // Lab-specific error columns, measured at the current settings; called at every point of any sweep, the lab's
    // knob or another.
    virtual SweepMetrics metrics(LabKit&, const Frame&) { return {}; }
    // The error the sweep's plot shows: one of metrics' columns, where the image's RMSE against the reference says
    // little (lab 05: particles restart at times that depend on the step); empty: the RMSE.
    virtual std::string error_column() const { return {}; }
};

}  // namespace gsv
