#include "deep_stack.h"

#include <exception>

#if defined(__SANITIZE_ADDRESS__)
// AddressSanitizer does not fully support switching stacks (it warns on every run), and its
// allocator has no per-thread arenas to avoid: there the reader gets a thread of its own.
#include <pthread.h>
#else
#include <sys/mman.h>
#include <ucontext.h>
#include <unistd.h>

#include <cstdint>
#endif

namespace lucent::sdl {

#if defined(__SANITIZE_ADDRESS__)

namespace {

struct Job {
  const std::function<void()>* work;
  std::exception_ptr error;
};

void* runJob(void* arg) {
  auto* job = static_cast<Job*>(arg);
  try {
    (*job->work)();
  } catch (...) {
    job->error = std::current_exception();
  }
  return nullptr;
}

}  // namespace

void runWithStack(std::size_t bytes, const std::function<void()>& work) {
  Job job{&work, nullptr};
  pthread_attr_t attr;
  pthread_t thread;
  bool started = false;
  if (pthread_attr_init(&attr) == 0) {
    started = pthread_attr_setstacksize(&attr, bytes) == 0 &&
              pthread_create(&thread, &attr, runJob, &job) == 0;
    pthread_attr_destroy(&attr);
  }
  if (!started) return work();
  pthread_join(thread, nullptr);
  if (job.error) std::rethrow_exception(job.error);
}

#else

namespace {

struct Job {
  const std::function<void()>* work;
  std::exception_ptr error;
  ucontext_t caller;
  ucontext_t callee;
};

// makecontext passes int arguments only: the job's address in two halves. Returning
// resumes the caller (uc_link).
void runJob(unsigned lo, unsigned hi) {
  auto* job = reinterpret_cast<Job*>((static_cast<std::uintptr_t>(hi) << 32) | lo);
  try {
    (*job->work)();
  } catch (...) {
    job->error = std::current_exception();
  }
}

}  // namespace

void runWithStack(std::size_t bytes, const std::function<void()>& work) {
  const auto guard = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  void* memory = mmap(nullptr, bytes + guard, PROT_READ | PROT_WRITE,
                      MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE | MAP_STACK, -1, 0);
  if (memory == MAP_FAILED) return work();
  // A reader that overran the stack would stop at the guard page, not write below it.
  mprotect(memory, guard, PROT_NONE);
  Job job{&work, nullptr, {}, {}};
  bool ran = false;
  if (getcontext(&job.callee) == 0) {
    job.callee.uc_stack.ss_sp = static_cast<char*>(memory) + guard;
    job.callee.uc_stack.ss_size = bytes;
    job.callee.uc_link = &job.caller;
    const auto address = reinterpret_cast<std::uintptr_t>(&job);
    makecontext(&job.callee, reinterpret_cast<void (*)()>(runJob), 2,
                static_cast<unsigned>(address & 0xffffffffu), static_cast<unsigned>(address >> 32));
    ran = swapcontext(&job.caller, &job.callee) == 0;
  }
  munmap(memory, bytes + guard);
  if (!ran) return work();
  if (job.error) std::rethrow_exception(job.error);
}

#endif

}  // namespace lucent::sdl
