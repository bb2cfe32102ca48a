// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrFuzzFieldMutation.h"

#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <type_traits>
#include <utility>

namespace vr::fuzz
{
namespace
{
template<typename T>
T
Swapped(T value)
{
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  for (std::size_t k = 0; k < sizeof(T) / 2; ++k)
  {
    std::swap(bytes[k], bytes[sizeof(T) - 1 - k]);
  }
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

template<typename T>
T
Load(const std::uint8_t * at, bool swapped)
{
  T value;
  std::memcpy(&value, at, sizeof(T));
  return swapped ? Swapped(value) : value;
}

template<typename T>
void
Store(std::uint8_t * at, T value, bool swapped)
{
  if (swapped)
  {
    value = Swapped(value);
  }
  std::memcpy(at, &value, sizeof(T));
}

template<typename T>
T
InterestingInteger(T current, Random & random)
{
  using Limits = std::numeric_limits<T>;
  using Unsigned = std::make_unsigned_t<T>; // wrapping arithmetic: a signed overflow here would be UBSan's finding
  const auto wrapped = static_cast<Unsigned>(current);
  switch (random.Below(8))
  {
    case 0:
      return Limits::max();
    case 1:
      return Limits::min();
    case 2:
      return static_cast<T>(static_cast<Unsigned>(wrapped + random.Below(5) - 2)); // a neighbour
    case 3:
      return static_cast<T>(-static_cast<long long>(random.Below(3))); // 0, -1, -2
    case 4:
      return static_cast<T>(static_cast<Unsigned>(Unsigned(1) << random.Below(sizeof(T) * 8 - 1))); // a power of two
    case 5:
    { // NIfTI's datatype codes and bit counts, DICOM's and NRRD's usual small numbers
      static const long long values[] = { 1,    2,    3,    4,    5,    7,    8,     12,    16,   24,  32,
                                          64,   128,  255,  256,  348,  352,  511,   512,   540,  768, 1024,
                                          1280, 1536, 1792, 2048, 2304, 2560, 32767, 65535, 65536 };
      return static_cast<T>(values[random.Below(std::size(values))]);
    }
    case 6:
      return static_cast<T>(static_cast<Unsigned>(wrapped * 2u));
    default:
      return static_cast<T>(random.Next());
  }
}

template<typename T>
T
InterestingFloat(T current, Random & random)
{
  using Limits = std::numeric_limits<T>;
  switch (random.Below(16))
  {
    case 0:
      return Limits::quiet_NaN();
    case 1:
      return Limits::infinity();
    case 2:
      return -Limits::infinity();
    case 3:
      return T(0);
    case 4:
      return -T(0);
    case 5:
      return T(-1);
    case 6:
      return Limits::denorm_min();
    case 7:
      return Limits::min();
    case 8:
      return Limits::max();
    case 9:
      return -Limits::max();
    case 10:
      return T(1e7) * (random.Below(2) == 0 ? T(1) : T(-1)); // past a plausibility bound
    case 11:
      return T(1e-6);
    case 12:
      return std::nextafter(current, random.Below(2) == 0 ? Limits::infinity() : -Limits::infinity());
    case 13:
      return current * T(-1);
    case 14:
      return T(random.Below(9)) - T(4); // small integers, as codes read as floats
    default:
      return static_cast<T>(std::ldexp(1.0, static_cast<int>(random.Below(256)) - 128));
  }
}
} // namespace

void
MutateField(std::uint8_t * header, const Field * fields, std::size_t fieldCount, bool swapped, Random & random)
{
  const Field &  field = fields[random.Below(fieldCount)];
  const unsigned index = static_cast<unsigned>(random.Below(field.count));
  switch (field.type)
  {
    case FieldType::Int8:
    {
      std::uint8_t * at = header + field.offset + index;
      *at = static_cast<std::uint8_t>(InterestingInteger<std::int8_t>(static_cast<std::int8_t>(*at), random));
      break;
    }
    case FieldType::Int16:
    {
      std::uint8_t * at = header + field.offset + 2 * index;
      Store(at, InterestingInteger(Load<std::int16_t>(at, swapped), random), swapped);
      break;
    }
    case FieldType::Int32:
    {
      std::uint8_t * at = header + field.offset + 4 * index;
      Store(at, InterestingInteger(Load<std::int32_t>(at, swapped), random), swapped);
      break;
    }
    case FieldType::Int64:
    {
      std::uint8_t * at = header + field.offset + 8 * index;
      Store(at, InterestingInteger(Load<std::int64_t>(at, swapped), random), swapped);
      break;
    }
    case FieldType::Float32:
    {
      std::uint8_t * at = header + field.offset + 4 * index;
      Store(at, InterestingFloat(Load<float>(at, swapped), random), swapped);
      break;
    }
    case FieldType::Float64:
    {
      std::uint8_t * at = header + field.offset + 8 * index;
      Store(at, InterestingFloat(Load<double>(at, swapped), random), swapped);
      break;
    }
  }
}

std::string
InterestingNumberText(Random & random)
{
  static const char * const values[] = { "nan",
                                         "NaN",
                                         "-nan",
                                         "inf",
                                         "-inf",
                                         "0",
                                         "-0",
                                         "-1",
                                         "1",
                                         "2",
                                         "3",
                                         "4",
                                         "1e308",
                                         "1e309",
                                         "-1e308",
                                         "4.9e-324",
                                         "1e-320",
                                         "1e-6",
                                         "1e7",
                                         "2147483647",
                                         "2147483648",
                                         "4294967296",
                                         "-2147483649",
                                         "65536",
                                         "9223372036854775807",
                                         "18446744073709551616",
                                         "0x10",
                                         "1.5",
                                         "",
                                         " ",
                                         "1,2",
                                         "(1,0,0)",
                                         "+",
                                         "." };
  return values[random.Below(std::size(values))];
}
} // namespace vr::fuzz
