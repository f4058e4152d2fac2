// Running the scene reader on a stack of its own: a POV-Ray scene nests objects, macros and
// directives by recursion (each bounded, objects at 256 deep), and the frames of that
// recursion are large (tokens, values and a PovObject per level), larger still under the
// sanitizers; a thread's default 8 MB is too little for the deepest nesting allowed there.
#pragma once

#include <cstddef>
#include <functional>

namespace lucent::sdl {

// Runs `work` on a new thread with a stack of `bytes` and waits for it; an exception it
// throws is thrown again here. Where no such thread can be made, runs it here.
void runWithStack(std::size_t bytes, const std::function<void()>& work);

}  // namespace lucent::sdl
