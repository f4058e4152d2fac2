#include "deep_stack.h"

#include <sys/mman.h>
#include <ucontext.h>
#include <unistd.h>

#include <cstdint>
#include <exception>

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/common_interface_defs.h>
#define LUCENT_ASAN_FIBERS 1
#endif

namespace lucent::sdl {

namespace {

struct Job {
  const std::function<void()>* work;
  std::exception_ptr error;
  ucontext_t caller;
  ucontext_t callee;
  // AddressSanitizer is told of each switch of stacks (its fiber annotations), so that it
  // checks the frames on the right one.
  const void* callerBottom = nullptr;
  std::size_t callerSize = 0;
};

// makecontext passes int arguments only: the job's address in two halves.
void runJob(unsigned lo, unsigned hi) {
  auto* job = reinterpret_cast<Job*>((static_cast<std::uintptr_t>(hi) << 32) | lo);
#ifdef LUCENT_ASAN_FIBERS
  __sanitizer_finish_switch_fiber(nullptr, &job->callerBottom, &job->callerSize);
#endif
  try {
    (*job->work)();
  } catch (...) {
    job->error = std::current_exception();
  }
#ifdef LUCENT_ASAN_FIBERS
  // This stack is left for good: nullptr lets AddressSanitizer drop its fake frames.
  __sanitizer_start_switch_fiber(nullptr, job->callerBottom, job->callerSize);
#endif
  swapcontext(&job->callee, &job->caller);
}

}  // namespace

void runWithStack(std::size_t bytes, const std::function<void()>& work) {
  const std::size_t guard = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  void* memory = mmap(nullptr, bytes + guard, PROT_READ | PROT_WRITE,
                      MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE | MAP_STACK, -1, 0);
  if (memory == MAP_FAILED) return work();
  // A reader that overran the stack would stop at the guard page, not write below it.
  mprotect(memory, guard, PROT_NONE);
  char* stack = static_cast<char*>(memory) + guard;
  Job job{&work, nullptr, {}, {}};
  bool ran = false;
  if (getcontext(&job.callee) == 0) {
    job.callee.uc_stack.ss_sp = stack;
    job.callee.uc_stack.ss_size = bytes;
    job.callee.uc_link = &job.caller;
    const auto address = reinterpret_cast<std::uintptr_t>(&job);
    makecontext(&job.callee, reinterpret_cast<void (*)()>(runJob), 2,
                static_cast<unsigned>(address & 0xffffffffu), static_cast<unsigned>(address >> 32));
#ifdef LUCENT_ASAN_FIBERS
    void* fakeStack = nullptr;
    __sanitizer_start_switch_fiber(&fakeStack, stack, bytes);
#endif
    ran = swapcontext(&job.caller, &job.callee) == 0;
#ifdef LUCENT_ASAN_FIBERS
    __sanitizer_finish_switch_fiber(fakeStack, nullptr, nullptr);
#endif
  }
  munmap(memory, bytes + guard);
  if (!ran) return work();
  if (job.error) std::rethrow_exception(job.error);
}

}  // namespace lucent::sdl
