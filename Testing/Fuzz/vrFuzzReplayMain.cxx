// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The main of a fuzz harness built without libFuzzer (GCC): runs LLVMFuzzerTestOneInput once on each file given
// (or on each file of each folder given), as a libFuzzer binary does with file arguments, so that the corpora are
// replayed as tests with both compilers.
#include "vrFuzzSupport.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <vector>

// The custom mutators' fallback: never called in a replay, but the harnesses that have one refer to it.
extern "C" std::size_t
LLVMFuzzerMutate(std::uint8_t *, std::size_t size, std::size_t)
{
  return size;
}

// A harness's set-up (libFuzzer calls it once before the first input), where the harness has one.
extern "C" __attribute__((weak)) int
LLVMFuzzerInitialize(int * argc, char *** argv);

int
main(int argc, char * argv[])
{
  if (LLVMFuzzerInitialize != nullptr)
  {
    LLVMFuzzerInitialize(&argc, &argv);
  }
  std::vector<std::filesystem::path> inputs;
  for (int k = 1; k < argc; ++k)
  {
    const std::filesystem::path argument(argv[k]);
    if (argument.string().rfind("-", 0) == 0)
    {
      continue; // libFuzzer flags (-runs=0, ...): a replay has none to honour
    }
    if (std::filesystem::is_directory(argument))
    {
      for (const auto & entry : std::filesystem::directory_iterator(argument))
      {
        inputs.push_back(entry.path());
      }
    }
    else
    {
      inputs.push_back(argument);
    }
  }
  std::sort(inputs.begin(), inputs.end());
  for (const auto & input : inputs)
  {
    std::ifstream file(input, std::ios::binary);
    if (!file)
    {
      std::cerr << "cannot read " << input << std::endl;
      return 1;
    }
    const std::vector<char> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    std::cout << "Running: " << input.string() << " (" << bytes.size() << " bytes)" << std::endl;
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t *>(bytes.data()), bytes.size());
  }
  std::cout << "Executed " << inputs.size() << " inputs" << std::endl;
  return 0;
}
