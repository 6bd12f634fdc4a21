#pragma once
// What the browser page is told about a lab, as JSON: its parameters (kind, range, choices, step, help, whether it
// has an effect now and why not), its named cases and its current values. The page builds its controls from this,
// so a parameter is declared once, in the lab, and reaches the page from its declaration.
//
// The one place outside params.cpp that reads parameter declarations for the page: when the Params API changes,
// this file follows it and the page does not.
#include "common/params/case_file.h"
#include "common/io/json.h"

#include <vector>

namespace gsv {

class Params;

// Every declared parameter in declaration order, with its value now.
Json describe_params(const Params& params);
// The values now and, for each parameter that has no effect under them, why ({"name": "...", "value": "...",
// "inactive": "needs field=file (it is rotation)"}): what the page refreshes after every change.
Json param_states(const Params& params);
// The named cases: name, description, settings, TODO (empty for a demo).
Json describe_cases(const std::vector<RenderCase>& cases);

}  // namespace gsv
