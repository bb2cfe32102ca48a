// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrFuzzSupport_h
#define vrFuzzSupport_h

#include <cstddef>
#include <cstdint>
#include <string>

/** What the fuzz harnesses share: each reads its input through the real reader, from a real file. */
namespace vr::fuzz
{
/** Writes \a data to a file named "input<extension>" in a folder of this process's own (under TMPDIR, removed at
 * exit), replacing the previous input, and returns its path. */
std::string
WriteInput(const std::uint8_t * data, std::size_t size, const std::string & extension);
} // namespace vr::fuzz

/** libFuzzer's entry point, defined by each harness. */
extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t * data, std::size_t size);

#endif
