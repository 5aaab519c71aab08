// The filter's parameters made from the library's option table (vorocrust/options.hpp).
//
// Each option becomes one parameter keyed by its MeshLab spelling (sharpAngle), labelled as the
// table labels it, its tooltip the table's help with the default and the range: a flag a RichBool,
// a whole number a RichInt, a number a RichFloat, a choice a RichEnum, a file a RichOpenFile, the
// box a RichString of six numbers, and a list of choices (the output formats) one RichBool per
// choice (formatsVtu). An option that may be unset (its default follows `smooth`, or means "none")
// shows unset as the table's unset_number (0 or -1), or as an empty text.
//
// MeshLab's numbers are single precision: a float parameter is read back through its shortest
// decimal text (0.0075f gives 0.0075), so that the value is the one the user typed, as the other
// front ends read it, and equal input gives equal output from every front end.
#pragma once

#include <string_view>
#include <vector>

#include "vorocrust/options.hpp"

class RichParameterList;

namespace vorocrust::meshlab {

// Adds the parameters of the table's MeshLab options, or of those named.
void add_option_parameters(RichParameterList& parameters, const std::vector<std::string_view>& names = {});

// The options the parameters hold (those present in `parameters`; the others keep their
// defaults). Throws Error(Usage) naming the option, in MeshLab's words (its label).
MeshOptions options_from_parameters(const RichParameterList& parameters);

// The key of the parameter of a list option's choice: formatsVtu.
QString choice_parameter(const OptionSpec& spec, std::string_view choice);

}  // namespace vorocrust::meshlab
