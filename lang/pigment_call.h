// Pigment functions (scenegraph/pigment_function.h) as muParser functions of three
// arguments: each call evaluates the pigment with the renderer's pattern evaluator, which
// is pure, so one parser per thread (expression_field.h) may call them concurrently.
#pragma once

#include <muParser.h>

#include <memory>
#include <vector>

namespace lucent {

struct PigmentFunction;

// Defines each of `pigments` in `parser` under its name. The parser keeps raw pointers:
// the caller keeps the pigment functions alive as long as the parser.
void definePigmentFunctions(mu::Parser& parser,
                            const std::vector<std::shared_ptr<const PigmentFunction>>& pigments);

// The call's value: the component of the pigment's colour at (x, y, z); NaN for a
// point that is not finite (the pattern evaluator needs finite points).
double pigmentFunctionValue(const PigmentFunction& f, double x, double y, double z);

}  // namespace lucent
