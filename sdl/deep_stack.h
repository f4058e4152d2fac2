// Running the scene reader on a stack of its own: a POV-Ray scene nests objects, macros and
// directives by recursion (each bounded, objects at 256 deep), and the frames of that
// recursion are large (tokens, values and a PovObject per level), larger still under the
// sanitizers; a thread's default 8 MB is too little for the deepest nesting allowed there.
//
// The stack is switched to on the calling thread (a ucontext), not given to a new thread:
// a new thread's allocations come from a malloc arena of its own, which glibc grows a page
// at a time with a system call each (2,300 of them reading language/vturbulence.pov), and
// the reader allocates much; the calling thread's arena grows in large steps. Under
// AddressSanitizer, which does not fully support switching stacks, it is a thread still.
#pragma once

#include <cstddef>
#include <functional>

namespace lucent::sdl {

// Runs `work` on a stack of `bytes` (with a guard page below it) on this thread and returns
// when it has; an exception it throws is thrown again here. Where no such stack can be
// mapped, runs it on this thread's own stack.
void runWithStack(std::size_t bytes, const std::function<void()>& work);

}  // namespace lucent::sdl
