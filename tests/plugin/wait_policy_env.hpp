// The environment of a wait-policy test's child (the CLIs' OpenMP wait
// policy, cli/wait_policy.cpp): libgomp's settings shown at start-up, and
// OMP_WAIT_POLICY and GOMP_SPINCOUNT set as given (nullptr: unset), until
// the end of the scope.
#pragma once

#include <cstdlib>
#include <optional>
#include <string>

namespace mcmd::test {

class WaitPolicyEnv {
 public:
  WaitPolicyEnv(const char* wait_policy, const char* spin_count) {
    set(0, "OMP_DISPLAY_ENV", "verbose");
    set(1, "OMP_WAIT_POLICY", wait_policy);
    set(2, "GOMP_SPINCOUNT", spin_count);
  }
  ~WaitPolicyEnv() {
    for (const Var& v : vars_) put(v.name, v.saved ? v.saved->c_str() : nullptr);
  }
  WaitPolicyEnv(const WaitPolicyEnv&) = delete;
  WaitPolicyEnv& operator=(const WaitPolicyEnv&) = delete;

 private:
  struct Var {
    const char* name = nullptr;
    std::optional<std::string> saved;
  };

  void set(int i, const char* name, const char* value) {
    vars_[i].name = name;
    if (const char* old = std::getenv(name)) vars_[i].saved = old;
    put(name, value);
  }
  static void put(const char* name, const char* value) {
    if (value) {
      setenv(name, value, 1);
    } else {
      unsetenv(name);
    }
  }

  Var vars_[3];
};

}  // namespace mcmd::test
