// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrFuzzFieldMutation_h
#define vrFuzzFieldMutation_h

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

/** What the structure-aware mutators share: a small random source, and values that break readers. */
namespace vr::fuzz
{
/** A xorshift generator seeded by libFuzzer's seed, so that a mutation can be replayed. */
class Random
{
public:
  explicit Random(unsigned int seed)
    : m_State(seed * 2654435761u + 0x9E3779B97F4A7C15ull)
  {
  }
  std::uint64_t
  Next()
  {
    m_State ^= m_State << 13;
    m_State ^= m_State >> 7;
    m_State ^= m_State << 17;
    return m_State;
  }
  /** A number in [0, n); 0 when n is 0. */
  std::size_t
  Below(std::size_t n)
  {
    return n == 0 ? 0 : static_cast<std::size_t>(Next() % n);
  }

private:
  std::uint64_t m_State;
};

enum class FieldType
{
  Int8,
  Int16,
  Int32,
  Int64,
  Float32,
  Float64
};

/** \a count consecutive values of \a type at byte \a offset of a binary header. */
struct Field
{
  std::size_t  offset;
  FieldType    type;
  unsigned int count;
};

/** Sets one value of one of \a fields (chosen at random) in \a header to a value that has broken readers (NaN,
 * infinities, 0, -1, a denormal, the type's extremes, a power of two, a neighbour of the value there, ...), in the
 * header's byte order (\a swapped: the other one than this machine's). The header must hold every field. */
void
MutateField(std::uint8_t * header, const Field * fields, std::size_t fieldCount, bool swapped, Random & random);

/** A number as text that has broken parsers: "nan", "-inf", "0", "-1", "1e308", "4.9e-324", "2147483648", ... */
std::string
InterestingNumberText(Random & random);
} // namespace vr::fuzz

#endif
