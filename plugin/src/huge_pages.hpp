// The CLI's memory policy (huge_pages.cpp): its operator new and heap settings.
#pragma once

namespace mcmd::cli {

// glibc's heap tuned for the fill's many field-sized buffers, freed and
// allocated again field after field on 2+ threads: 1201² blob fill, page
// faults 17 000 -> 12 000. Call first thing in main, before any thread starts.
void tune_heap();

}  // namespace mcmd::cli
