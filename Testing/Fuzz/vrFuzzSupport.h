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

/** The folder WriteInput() writes into (under TMPDIR, this process's own, removed at exit). */
std::string
InputFolder();

/** Reads the volume at \a path as the modules do (vr::ReadVolume), swallowing vr::InputError; the voxels are read
 * only when the header asks for at most 2^22 of them, so that a header that asks for gigabytes (which the reader
 * allows for a real volume) is not taken for a finding by -malloc_limit_mb. */
void
ReadVolumeOfBoundedSize(const std::string & path);
} // namespace vr::fuzz

/** libFuzzer's byte-level mutator, for the custom mutators to fall back on (a stub in the replay build). */
extern "C" std::size_t
LLVMFuzzerMutate(std::uint8_t * data, std::size_t size, std::size_t maxSize);

/** libFuzzer's entry point, defined by each harness. */
extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t * data, std::size_t size);

#endif
