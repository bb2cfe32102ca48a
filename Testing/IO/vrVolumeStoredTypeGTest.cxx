// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Volumes read in the pixel type of their file (issue 40, docs/design.md "Volumes in their stored type"): every
// format keeps the stored type and the values, NIfTI's scl_slope and scl_inter become the rescale, and the float
// intensities equal ITK's own float read of the same file, bit for bit. NIfTI voxels go through our own reader:
// byte order, compression, truncation and NaN. A volume that does not fit in memory is refused before it is read.
#include "vrInputError.h"
#include "vrTestFiles.h"
#include "vrTestNifti.h"
#include "vrText.h"
#include "vrVolumeIO.h"

#include "itkCPRVectorHelpers.h"
#include "itkImageFileReader.h"
#include "itkImageFileWriter.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <random>
#include <sys/resource.h>
#include <type_traits>

namespace
{
using vr::test::InputErrorOf;
template<typename TPixel>
using Volume = itk::Image<TPixel, 3>;

#define EXPECT_MESSAGE_HAS(message, part)                                                                              \
  EXPECT_NE((message).find(part), std::string::npos) << "message: " << (message) << "\nmissing: " << (part)

/** A 7 x 5 x 6 volume of TPixel with anisotropic spacing, an offset origin and a rotation, random values over the
 * type's range (whole numbers for integers). */
template<typename TPixel>
typename Volume<TPixel>::Pointer
MakeVolume(unsigned int seed)
{
  auto                                volume = Volume<TPixel>::New();
  typename Volume<TPixel>::RegionType region;
  region.SetSize({ { 7, 5, 6 } });
  volume->SetRegions(region);
  volume->SetSpacing(itk::detail::MakeVector3(0.5, 0.75, 1.25));
  typename Volume<TPixel>::PointType origin;
  origin[0] = 10.0;
  origin[1] = -20.0;
  origin[2] = 30.0;
  volume->SetOrigin(origin);
  typename Volume<TPixel>::DirectionType direction;
  direction.Fill(0.0);
  direction(0, 1) = -1.0;
  direction(1, 0) = 1.0;
  direction(2, 2) = 1.0;
  volume->SetDirection(direction);
  volume->Allocate();
  const double low = std::is_integral_v<TPixel> ? static_cast<double>(std::numeric_limits<TPixel>::lowest()) : -3000.0;
  const double high = std::is_integral_v<TPixel> ? static_cast<double>(std::numeric_limits<TPixel>::max()) : 3000.0;
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> values(low, high);
  for (std::size_t k = 0; k < region.GetNumberOfPixels(); ++k)
  {
    const double value = values(generator);
    volume->GetBufferPointer()[k] = static_cast<TPixel>(std::is_integral_v<TPixel> ? std::round(value) : value);
  }
  return volume;
}

template<typename TImage>
void
WriteWithITK(const TImage * image, const std::string & path, bool compress)
{
  auto writer = itk::ImageFileWriter<TImage>::New();
  writer->SetInput(image);
  writer->SetFileName(path);
  writer->SetUseCompression(compress);
  writer->Update();
}

/** ITK's own read of \a path as float: what vr::ReadVolume returned before volumes kept their type. */
vr::VolumeImageType::Pointer
ITKFloatRead(const std::string & path)
{
  auto reader = itk::ImageFileReader<vr::VolumeImageType>::New();
  reader->SetFileName(path);
  reader->Update();
  return reader->GetOutput();
}

void
ExpectSameGrid(const itk::ImageBase<3> * actual, const itk::ImageBase<3> * expected)
{
  ASSERT_EQ(actual->GetLargestPossibleRegion(), expected->GetLargestPossibleRegion());
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    EXPECT_NEAR(actual->GetSpacing()[axis], expected->GetSpacing()[axis], 1e-6);
    EXPECT_NEAR(actual->GetOrigin()[axis], expected->GetOrigin()[axis], 1e-5);
    for (unsigned int column = 0; column < 3; ++column)
    {
      EXPECT_NEAR(actual->GetDirection()(axis, column), expected->GetDirection()(axis, column), 1e-6);
    }
  }
}

void
ExpectSameFloats(const vr::VolumeImageType * actual, const vr::VolumeImageType * expected)
{
  ExpectSameGrid(actual, expected);
  const std::size_t count = expected->GetLargestPossibleRegion().GetNumberOfPixels();
  EXPECT_EQ(std::memcmp(actual->GetBufferPointer(), expected->GetBufferPointer(), count * sizeof(float)), 0);
}

const char * const Extensions[] = { ".nrrd", ".nhdr", ".nii", ".nii.gz", ".mha", ".mhd" };

/** Writes a TPixel volume in every format, plain and compressed, and reads it back as stored and as float. */
template<typename TPixel>
void
ExpectEveryFormatKeepsTheType(itk::IOComponentEnum expectedType)
{
  const vr::test::ScopedTemporaryFolder folder;
  const auto                            volume = MakeVolume<TPixel>(7);
  for (const std::string extension : Extensions)
  {
    for (const bool compress : { false, true })
    {
      if (compress && (extension == ".nii" || extension == ".nii.gz"))
      {
        continue; // NIfTI is compressed by its name
      }
      SCOPED_TRACE(extension + (compress ? " compressed" : ""));
      const std::string path = folder.File(std::string("volume") + (compress ? "-gz" : "") + extension);
      WriteWithITK(volume.GetPointer(), path, compress);
      const vr::StoredVolume stored = vr::ReadStoredVolume(path);
      ASSERT_EQ(stored.GetPixelType(), expectedType);
      EXPECT_TRUE(stored.Rescale.IsIdentity());
      ExpectSameGrid(stored.Image, volume);
      const auto * image = dynamic_cast<const Volume<TPixel> *>(stored.Image.GetPointer());
      ASSERT_NE(image, nullptr);
      EXPECT_EQ(std::memcmp(image->GetBufferPointer(),
                            volume->GetBufferPointer(),
                            volume->GetLargestPossibleRegion().GetNumberOfPixels() * sizeof(TPixel)),
                0);
      ExpectSameFloats(vr::ReadVolume(path), ITKFloatRead(path));
    }
  }
}

/** A NIfTI-1 single file (.nii, or gzip-compressed .nii.gz) of int16 voxels (vr::test::Nifti1Header), in either byte
 * order, with scl_slope and scl_inter; \a truncateTo > 0 cuts the file to that many bytes. */
void
WriteNiftiInt16(const std::string &        path,
                const itk::Size<3> &       size,
                const std::vector<short> & voxels,
                float                      slope,
                float                      intercept,
                bool                       bigEndian,
                std::size_t                truncateTo = 0)
{
  const double               spacing[3] = { 0.5, 0.75, 1.25 };
  std::vector<unsigned char> bytes = vr::test::Nifti1Header(size, 4, 16, spacing, slope, intercept, bigEndian);
  for (const short voxel : voxels)
  {
    unsigned char raw[2];
    std::memcpy(raw, &voxel, 2);
    if (bigEndian)
    {
      std::swap(raw[0], raw[1]);
    }
    bytes.push_back(raw[0]);
    bytes.push_back(raw[1]);
  }
  if (truncateTo > 0)
  {
    bytes.resize(truncateTo);
  }
  if (vr::EndsWith(path, ".gz"))
  {
    gzFile file = gzopen(path.c_str(), "wb");
    ASSERT_NE(file, nullptr);
    ASSERT_EQ(gzwrite(file, bytes.data(), static_cast<unsigned>(bytes.size())), static_cast<int>(bytes.size()));
    gzclose(file);
    return;
  }
  std::ofstream file(path, std::ios::binary);
  file.write(reinterpret_cast<const char *>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

/** The bytes of \a voxels as a file holds them: in the machine's (little-endian) order, swapped for \a bigEndian. */
std::string
BytesOf(const std::vector<short> & voxels, bool bigEndian)
{
  std::string bytes;
  for (const short voxel : voxels)
  {
    char raw[2];
    std::memcpy(raw, &voxel, 2);
    if (bigEndian)
    {
      std::swap(raw[0], raw[1]);
    }
    bytes.append(raw, 2);
  }
  return bytes;
}

std::vector<short>
RandomShorts(std::size_t count, unsigned int seed)
{
  std::mt19937                       generator(seed);
  std::uniform_int_distribution<int> values(-1024, 3071);
  std::vector<short>                 result(count);
  for (auto & value : result)
  {
    value = static_cast<short>(values(generator));
  }
  return result;
}

/** Reads \a path and checks it is the int16 volume written: \a voxels in order, \a size, and the spacing and origin
 * the hand-written headers here give ((0.5, 0.75, 1.25) mm, (1, 2, 3)). */
void
ExpectTheWrittenShorts(const std::string & path, const std::vector<short> & voxels, const itk::Size<3> & size)
{
  const vr::StoredVolume stored = vr::ReadStoredVolume(path);
  ASSERT_EQ(stored.GetPixelType(), itk::IOComponentEnum::SHORT);
  const auto * image = dynamic_cast<const Volume<short> *>(stored.Image.GetPointer());
  ASSERT_NE(image, nullptr);
  EXPECT_EQ(std::vector<short>(image->GetBufferPointer(), image->GetBufferPointer() + voxels.size()), voxels);
  EXPECT_EQ(image->GetLargestPossibleRegion().GetSize(), size);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[1], 0.75);
  EXPECT_DOUBLE_EQ(image->GetOrigin()[2], 3.0);
}
} // namespace

TEST(VolumeStoredType, EveryFormatKeepsInt16)
{
  ExpectEveryFormatKeepsTheType<short>(itk::IOComponentEnum::SHORT);
}

TEST(VolumeStoredType, EveryFormatKeepsTheOtherStoredTypes)
{
  {
    SCOPED_TRACE("uint16");
    ExpectEveryFormatKeepsTheType<unsigned short>(itk::IOComponentEnum::USHORT);
  }
  {
    SCOPED_TRACE("uint8");
    ExpectEveryFormatKeepsTheType<unsigned char>(itk::IOComponentEnum::UCHAR);
  }
  {
    SCOPED_TRACE("int8");
    ExpectEveryFormatKeepsTheType<signed char>(itk::IOComponentEnum::CHAR);
  }
  {
    SCOPED_TRACE("float");
    ExpectEveryFormatKeepsTheType<float>(itk::IOComponentEnum::FLOAT);
  }
  {
    SCOPED_TRACE("double");
    ExpectEveryFormatKeepsTheType<double>(itk::IOComponentEnum::DOUBLE);
  }
}

// 32-bit integers are no stored type: they are read as float, as before.
TEST(VolumeStoredType, Int32IsReadAsFloat)
{
  const vr::test::ScopedTemporaryFolder folder;
  const auto                            volume = MakeVolume<int>(3);
  for (const std::string extension : { ".nrrd", ".nii.gz", ".mha" })
  {
    SCOPED_TRACE(extension);
    const std::string path = folder.File("ints" + extension);
    WriteWithITK(volume.GetPointer(), path, false);
    const vr::StoredVolume stored = vr::ReadStoredVolume(path);
    EXPECT_EQ(stored.GetPixelType(), itk::IOComponentEnum::FLOAT);
    ExpectSameFloats(vr::ReadVolume(path), ITKFloatRead(path));
  }
}

// NIfTI's scl_slope and scl_inter: the voxels stay int16 and the rescale travels beside them; as float, the values
// ITK's NIfTI reader gives (it turns them into float itself), bit for bit. In either byte order, plain and gzip.
TEST(VolumeStoredType, NiftiRescaleKeepsInt16InEitherByteOrder)
{
  const vr::test::ScopedTemporaryFolder folder;
  const itk::Size<3>                    size = { { 9, 4, 5 } };
  const std::vector<short>              voxels = RandomShorts(9 * 4 * 5, 19);
  for (const bool bigEndian : { false, true })
  {
    for (const std::string name : { "ct.nii", "ct.nii.gz" })
    {
      SCOPED_TRACE(name + (bigEndian ? " big-endian" : " little-endian"));
      const std::string path = folder.File((bigEndian ? "be-" : "le-") + name);
      WriteNiftiInt16(path, size, voxels, 0.5f, -1024.0f, bigEndian);
      const vr::StoredVolume stored = vr::ReadStoredVolume(path);
      ASSERT_EQ(stored.GetPixelType(), itk::IOComponentEnum::SHORT);
      EXPECT_EQ(stored.Rescale.Slope, 0.5);
      EXPECT_EQ(stored.Rescale.Intercept, -1024.0);
      const auto * image = dynamic_cast<const Volume<short> *>(stored.Image.GetPointer());
      ASSERT_NE(image, nullptr);
      EXPECT_EQ(std::memcmp(image->GetBufferPointer(), voxels.data(), voxels.size() * sizeof(short)), 0);
      ExpectSameFloats(vr::ReadVolume(path), ITKFloatRead(path));
    }
  }
  // scl_slope 0 means no rescale (NIfTI-1); so do 1 and 0.
  for (const float slope : { 0.0f, 1.0f })
  {
    const std::string path = folder.File("plain.nii");
    WriteNiftiInt16(path, size, voxels, slope, 0.0f, false);
    EXPECT_TRUE(vr::ReadStoredVolume(path).Rescale.IsIdentity()) << "scl_slope " << slope;
  }
}

TEST(VolumeStoredType, TruncatedNiftiIsRefused)
{
  const vr::test::ScopedTemporaryFolder folder;
  const itk::Size<3>                    size = { { 9, 4, 5 } };
  const std::vector<short>              voxels = RandomShorts(9 * 4 * 5, 19);
  for (const std::string name : { "short.nii", "short.nii.gz" })
  {
    const std::string path = folder.File(name);
    WriteNiftiInt16(path, size, voxels, 1.0f, 0.0f, false, 352 + 300);
    const std::string message = InputErrorOf([&] { vr::ReadStoredVolume(path); });
    EXPECT_MESSAGE_HAS(message, path);
    EXPECT_MESSAGE_HAS(message, "truncated");
  }
}

// A NaN voxel in a NIfTI file is named, as in the other formats (the NIfTI library would have made it 0 silently).
TEST(VolumeStoredType, NanInNiftiIsNamed)
{
  const vr::test::ScopedTemporaryFolder folder;
  auto                                  volume = MakeVolume<float>(5);
  volume->SetPixel({ { 3, 2, 4 } }, std::nanf(""));
  const std::string path = folder.File("nan.nii.gz");
  WriteWithITK(volume.GetPointer(), path, false);
  const std::string message = InputErrorOf([&] { vr::ReadStoredVolume(path); });
  EXPECT_MESSAGE_HAS(message, "voxel (3, 2, 4) is nan");
}

// A volume larger than the memory left is refused before anything is allocated, naming the bytes needed and
// available: here under an address-space limit (RLIMIT_AS, as `ulimit -v` sets) of 512 MiB above what the process
// uses, a header declaring 2 GiB of voxels.
TEST(VolumeStoredType, AVolumeThatDoesNotFitIsRefusedNamingTheBytes)
{
  const vr::test::ScopedTemporaryFolder folder;
  vr::test::WriteTextFile(folder.File("huge.raw"), std::string(4096, '\0'));
  const std::string header = folder.File("huge.nhdr");
  vr::test::WriteTextFile(header,
                          "NRRD0004\ntype: uint8\ndimension: 3\nspace: left-posterior-superior\nsizes: 2048 1024 1024\n"
                          "space directions: (1,0,0) (0,1,0) (0,0,1)\nspace origin: (0,0,0)\nencoding: raw\n"
                          "data file: huge.raw\n\n");
  rlimit before{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &before), 0);
  std::ifstream status("/proc/self/status");
  std::string   line;
  double        used = 0.0;
  while (std::getline(status, line))
  {
    if (line.rfind("VmSize:", 0) == 0)
    {
      used = std::stod(line.substr(7)) * 1024.0;
    }
  }
  ASSERT_GT(used, 0.0);
  rlimit limited = before;
  limited.rlim_cur = static_cast<rlim_t>(used) + (rlim_t{ 512 } << 20);
  if (before.rlim_cur != RLIM_INFINITY && limited.rlim_cur > before.rlim_cur)
  {
    limited.rlim_cur = before.rlim_cur;
  }
  ASSERT_EQ(setrlimit(RLIMIT_AS, &limited), 0);
  const std::string message = InputErrorOf([&] { vr::ReadStoredVolume(header); });
  ASSERT_EQ(setrlimit(RLIMIT_AS, &before), 0);
  EXPECT_MESSAGE_HAS(message, header);
  EXPECT_MESSAGE_HAS(message, "2147483648 voxels of uint8 need 2 GiB (2,147,483,648 bytes) of memory");
  EXPECT_MESSAGE_HAS(message, "available");
}

// A raw NRRD with its header attached and its voxels in the machine's byte order is read straight into the buffer
// (vrNrrdRawVoxels.h: teem would zero the buffer first); any other raw NRRD goes through ITK. The values are the ones
// written, whichever way: hand-written headers with comments and key/value pairs, the other byte order, trailing
// bytes, a byte skip, one-byte voxels without an endian field; a file cut short is refused as before.
TEST(VolumeStoredType, RawNrrdIsReadStraightIntoTheBufferAndEveryOtherThroughITK)
{
  const vr::test::ScopedTemporaryFolder folder;
  const std::vector<short>              voxels = RandomShorts(4 * 3 * 2, 11);
  const auto                            bytesOf = [&](bool bigEndian) { return BytesOf(voxels, bigEndian); };
  const std::string fields = "type: short\ndimension: 3\nspace: left-posterior-superior\nsizes: 4 3 2\n"
                             "space directions: (0.5,0,0) (0,0.75,0) (0,0,1.25)\nspace origin: (1,2,3)\n"
                             "encoding: raw\n";
  struct Case
  {
    std::string Name;
    std::string Text;
  };
  const std::vector<Case> cases{
    { "attached",
      "NRRD0004\n# a comment: with a colon\n" + fields + "endian: little\nscanner:=CT 1\n\n" + bytesOf(false) },
    { "big-endian", "NRRD0004\n" + fields + "endian: big\n\n" + bytesOf(true) },
    { "trailing-bytes", "NRRD0004\n" + fields + "endian: little\n\n" + bytesOf(false) + "extra" },
    { "byte-skip", "NRRD0004\n" + fields + "endian: little\nbyte skip: 6\n\nskip!!" + bytesOf(false) },
  };
  for (const Case & c : cases)
  {
    SCOPED_TRACE(c.Name);
    const std::string path = folder.File(c.Name + ".nrrd");
    std::ofstream(path, std::ios::binary) << c.Text;
    ExpectTheWrittenShorts(path, voxels, { { 4, 3, 2 } });
  }

  // One-byte voxels: no endian field is needed.
  const std::string bytePath = folder.File("bytes.nrrd");
  std::ofstream(bytePath, std::ios::binary) << "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\n"
                                            << std::string("\x01\x02\x03\x04\xfb\xfc\xfd\xfe", 8);
  const vr::StoredVolume bytes = vr::ReadStoredVolume(bytePath);
  ASSERT_EQ(bytes.GetPixelType(), itk::IOComponentEnum::UCHAR);
  const auto * byteImage = dynamic_cast<const Volume<unsigned char> *>(bytes.Image.GetPointer());
  ASSERT_NE(byteImage, nullptr);
  EXPECT_EQ(std::vector<int>(byteImage->GetBufferPointer(), byteImage->GetBufferPointer() + 8),
            (std::vector<int>{ 1, 2, 3, 4, 251, 252, 253, 254 }));

  // Cut short by one byte: refused, naming the file and the voxel data.
  const std::string cut = folder.File("cut.nrrd");
  const std::string whole = "NRRD0004\n" + fields + "endian: little\n\n" + bytesOf(false);
  std::ofstream(cut, std::ios::binary) << whole.substr(0, whole.size() - 1);
  const std::string message = InputErrorOf([&] { vr::ReadStoredVolume(cut); });
  EXPECT_MESSAGE_HAS(message, cut);
  EXPECT_MESSAGE_HAS(message, "voxel data");
}

namespace
{
/** \a bytes deflated as a zlib stream (what MetaIO writes), or a gzip one. */
std::string
Deflated(const std::string & bytes, bool gzip)
{
  z_stream stream{};
  EXPECT_EQ(deflateInit2(&stream, 6, Z_DEFLATED, gzip ? 15 + 16 : 15, 8, Z_DEFAULT_STRATEGY), Z_OK);
  std::string out(deflateBound(&stream, bytes.size()) + 32, '\0');
  stream.next_in = reinterpret_cast<Bytef *>(const_cast<char *>(bytes.data()));
  stream.avail_in = static_cast<uInt>(bytes.size());
  stream.next_out = reinterpret_cast<Bytef *>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(deflate(&stream, Z_FINISH), Z_STREAM_END);
  out.resize(stream.total_out);
  deflateEnd(&stream);
  return out;
}
} // namespace

// A compressed MetaImage is inflated straight into the volume's buffer (vrMetaImageVoxels.h), in pieces, in either
// byte order, LOCAL or detached, zlib or gzip; a stream cut short, damaged or longer than the header says is refused.
// The expected voxels are the ones written, byte for byte.
TEST(VolumeStoredType, CompressedMetaImageIsInflatedStraightIntoTheBuffer)
{
  const vr::test::ScopedTemporaryFolder folder;
  const std::vector<short>              voxels = RandomShorts(9 * 7 * 5, 23);
  const auto                            bytesOf = [&](bool bigEndian) { return BytesOf(voxels, bigEndian); };
  const auto                            header = [](bool bigEndian, const std::string & dataFile)
  {
    return "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = " +
           std::string(bigEndian ? "True" : "False") +
           "\nCompressedData = True\nTransformMatrix = 1 0 0 0 1 0 0 0 1\nOffset = 1 2 3\n"
           "ElementSpacing = 0.5 0.75 1.25\nDimSize = 9 7 5\nElementType = MET_SHORT\nElementDataFile = " +
           dataFile + "\n";
  };
  struct Case
  {
    std::string Name;
    std::string Header;
    std::string DataFile; // empty: LOCAL
    std::string Stream;
  };
  const std::vector<Case> cases{
    { "local", header(false, "LOCAL"), "", Deflated(bytesOf(false), false) },
    { "big-endian", header(true, "LOCAL"), "", Deflated(bytesOf(true), false) },
    { "gzip", header(false, "LOCAL"), "", Deflated(bytesOf(false), true) },
    { "detached", header(false, "detached.zraw"), "detached.zraw", Deflated(bytesOf(false), false) },
  };
  for (const Case & c : cases)
  {
    SCOPED_TRACE(c.Name);
    const std::string path = folder.File(c.Name + (c.DataFile.empty() ? ".mha" : ".mhd"));
    if (c.DataFile.empty())
    {
      std::ofstream(path, std::ios::binary) << c.Header << c.Stream;
    }
    else
    {
      std::ofstream(path, std::ios::binary) << c.Header;
      std::ofstream(folder.File(c.DataFile), std::ios::binary) << c.Stream;
    }
    ExpectTheWrittenShorts(path, voxels, { { 9, 7, 5 } });
  }

  const std::string stream = Deflated(bytesOf(false), false);
  const auto        refusal = [&](const std::string & name, const std::string & text)
  {
    const std::string path = folder.File(name + ".mha");
    std::ofstream(path, std::ios::binary) << text;
    const std::string message = InputErrorOf([&] { vr::ReadStoredVolume(path); });
    EXPECT_MESSAGE_HAS(message, path);
    EXPECT_MESSAGE_HAS(message, "voxel data");
    return message;
  };
  {
    SCOPED_TRACE("cut short");
    const std::string message = refusal("cut", header(false, "LOCAL") + stream.substr(0, stream.size() / 2));
    EXPECT_MESSAGE_HAS(message, "truncated");
  }
  {
    SCOPED_TRACE("damaged");
    std::string damaged = stream;
    for (std::size_t k = 2; k < damaged.size() - 4; k += 7)
    {
      damaged[k] = static_cast<char>(damaged[k] ^ 0x5A);
    }
    refusal("damaged", header(false, "LOCAL") + damaged);
  }
  {
    SCOPED_TRACE("longer than the header says");
    const std::string message =
      refusal("longer", header(false, "LOCAL") + Deflated(bytesOf(false) + std::string("\x01\x02", 2), false));
    EXPECT_MESSAGE_HAS(message, "holds more than the header's 630 voxel bytes");
  }
  {
    SCOPED_TRACE("not compressed at all");
    const std::string message = refusal("plain", header(false, "LOCAL") + bytesOf(false));
    EXPECT_MESSAGE_HAS(message, "damaged");
  }
}
