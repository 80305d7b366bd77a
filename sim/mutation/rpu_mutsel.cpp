// The mutant selector of a mutation build (scripts/mutate.py): the mutated design imports
// rpu_mutsel() through DPI and reads it once at time zero; 0 (or RPU_MUTSEL unset) runs the
// unmutated design, k > 0 activates mutant k.
#include <cstdlib>

extern "C" int rpu_mutsel() {
  const char* s = std::getenv("RPU_MUTSEL");
  return s ? std::atoi(s) : 0;
}
