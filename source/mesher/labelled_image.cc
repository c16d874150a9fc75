#include <fcntl.h>
#include <nifti2_io.h>
#include <restshape/base/atomic_file.h>
#include <restshape/base/input_error.h>
#include <restshape/base/machine_memory.h>
#include <restshape/mesher/labelled_image.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>

namespace RestShape
{
  std::array<double, 3>
  LabelledImage::spacing() const
  {
    std::array<double, 3> h;
    for (unsigned int d = 0; d < 3; ++d)
      {
        double s = 0;
        for (unsigned int r = 0; r < 3; ++r)
          s += index_to_mm[r][d] * index_to_mm[r][d];
        h[d] = std::sqrt(s);
      }
    return h;
  }

  dealii::Point<3>
  LabelledImage::position(const double i, const double j, const double k) const
  {
    dealii::Tensor<1, 3> ijk;
    ijk[0] = i;
    ijk[1] = j;
    ijk[2] = k;
    return dealii::Point<3>(index_to_mm * ijk + offset);
  }
  ImageLabel
  LabelledImage::label_at(const dealii::Point<3> &x) const
  {
    dealii::Tensor<1, 3> relative = x;
    relative -= offset;
    const dealii::Tensor<1, 3>  ijk = dealii::invert(index_to_mm) * relative;
    std::array<unsigned int, 3> n;
    for (unsigned int d = 0; d < 3; ++d)
      {
        const double rounded = std::round(ijk[d]);
        if (!(rounded >= 0 && rounded < size[d]))
          return 0;
        n[d] = static_cast<unsigned int>(rounded);
      }
    return labels[index(n[0], n[1], n[2])];
  }


  std::map<unsigned int, std::size_t>
  LabelledImage::label_counts() const
  {
    std::map<unsigned int, std::size_t> counts;
    for (const ImageLabel l : labels)
      if (l != 0)
        ++counts[l];
    return counts;
  }

  ImageLabel
  LabelledImage::max_label() const
  {
    return labels.empty() ? 0 : *std::max_element(labels.begin(), labels.end());
  }

  unsigned int
  LabelledImage::label_bytes() const
  {
    const ImageLabel top = max_label();
    return top <= 255 ? 1 : top <= 65535 ? 2 : 4;
  }

  void
  LabelledImage::store_labels(void *data) const
  {
    const unsigned int bytes = label_bytes();
    for (std::size_t v = 0; v < labels.size(); ++v)
      if (bytes == 1)
        static_cast<std::uint8_t *>(data)[v] = labels[v];
      else if (bytes == 2)
        static_cast<std::uint16_t *>(data)[v] = labels[v];
      else
        static_cast<std::uint32_t *>(data)[v] = labels[v];
  }

  namespace
  {
    struct NiftiDeleter
    {
      void
      operator()(nifti_image *image) const
      {
        nifti_image_free(image);
      }
    };

    template <typename T>
    void
    convert(const void *data, const std::size_t n, std::vector<double> &values)
    {
      const T *typed = static_cast<const T *>(data);
      values.assign(typed, typed + n);
    }
  } // namespace

  namespace
  {
    /// Voxel sizes of an image, in mm, from microscopy to a coarse scan
    /// (beyond them the header's units are wrong).
    constexpr double smallest_voxel_mm = 1e-4;
    constexpr double largest_voxel_mm  = 1e3;
    /// The largest distance of the image's origin from the scanner's, mm.
    constexpr double largest_offset_mm = 1e6;

    /// The process's standard error goes to /dev/null while it lives.
    class SilencedStderr
    {
    public:
      SilencedStderr()
        : saved(::dup(STDERR_FILENO))
      {
        std::fflush(stderr);
        const int null = ::open("/dev/null", O_WRONLY);
        if (null >= 0)
          {
            ::dup2(null, STDERR_FILENO);
            ::close(null);
          }
      }
      ~SilencedStderr()
      {
        std::fflush(stderr);
        if (saved >= 0)
          {
            ::dup2(saved, STDERR_FILENO);
            ::close(saved);
          }
      }

    private:
      const int saved;
    };

    /// The bytes of voxels @p header declares, against the file's size
    /// (uncompressed) or half the machine's memory (.gz).
    void
    check_declared_size(const nifti_image &header,
                        const std::string &file,
                        const std::string &parameter)
    {
      const double    declared = double(header.nvox) * header.nbyper;
      std::error_code ec;
      const double    size = std::filesystem::file_size(file, ec);
      const bool      compressed =
        file.size() > 3 && file.compare(file.size() - 3, 3, ".gz") == 0;
      const double limit =
        compressed ? 0.5 * physical_memory_bytes() : (ec ? 0. : size);
      if (declared > limit && limit > 0)
        throw InputError(file,
                         parameter,
                         "the header declares " + number_text(header.nvox) +
                           " voxels (" + number_text(declared) +
                           " bytes), more than the file " +
                           (compressed ? "could hold in memory" : "holds") +
                           "; expected a header that matches its image");
    }

    /// The header's voxel sizes pixdim[1..3] as written (libnifti makes a
    /// zero or non-finite one 1 mm); ones if the header cannot be read
    /// (the image's own read reports that).
    std::array<double, 3>
    written_voxel_sizes(const std::string &file)
    {
      int                   version = 0;
      void                 *raw = nifti_read_header(file.c_str(), &version, 0);
      std::array<double, 3> h   = {{1, 1, 1}};
      if (raw != nullptr && version == 1)
        for (unsigned int d = 0; d < 3; ++d)
          h[d] = static_cast<nifti_1_header *>(raw)->pixdim[d + 1];
      else if (raw != nullptr && version == 2)
        for (unsigned int d = 0; d < 3; ++d)
          h[d] = static_cast<nifti_2_header *>(raw)->pixdim[d + 1];
      std::free(raw);
      return h;
    }

    /// The index of the first voxel of a float image that is not a finite
    /// number as written (libnifti makes them 0, background), or -1.
    long long
    first_nonfinite_voxel(const nifti_image &nim)
    {
      if (nim.datatype != DT_FLOAT32 && nim.datatype != DT_FLOAT64)
        return -1;
      znzFile in = znzopen(nim.iname, "rb", nifti_is_gzfile(nim.iname));
      if (znz_isnull(in))
        return -1;
      znzseek(in, nim.iname_offset, SEEK_SET);
      const bool        swap  = nim.byteorder != nifti_short_order();
      const size_t      bytes = nim.datatype == DT_FLOAT32 ? 4 : 8;
      constexpr size_t  chunk = 1 << 16; // voxels per read
      std::vector<char> buffer(chunk * bytes);
      long long         found = -1;
      for (long long start = 0; start < nim.nvox && found < 0; start += chunk)
        {
          const size_t n = std::min<long long>(chunk, nim.nvox - start);
          if (znzread(buffer.data(), bytes, n, in) != n)
            break;
          if (swap)
            bytes == 4 ? nifti_swap_4bytes(n, buffer.data()) :
                         nifti_swap_8bytes(n, buffer.data());
          for (size_t i = 0; i < n && found < 0; ++i)
            {
              double v;
              if (bytes == 4)
                {
                  float f;
                  std::memcpy(&f, buffer.data() + 4 * i, 4);
                  v = f;
                }
              else
                std::memcpy(&v, buffer.data() + 8 * i, 8);
              if (!std::isfinite(v))
                found = start + i;
            }
        }
      znzclose(in);
      return found;
    }

    /// Voxel sizes and origin within the bounds above.
    void
    check_geometry(const LabelledImage &image,
                   const std::string   &file,
                   const std::string   &parameter)
    {
      for (const double h : image.spacing())
        if (!(h >= smallest_voxel_mm && h <= largest_voxel_mm))
          throw InputError(file,
                           parameter,
                           "a voxel size of " + number_text(h) +
                             " mm in the header; expected " +
                             number_text(smallest_voxel_mm) + " to " +
                             number_text(largest_voxel_mm) +
                             " mm (pixdim, or the sform/qform, in mm)");
      for (unsigned int d = 0; d < 3; ++d)
        if (!(std::abs(image.offset[d]) <= largest_offset_mm))
          throw InputError(file,
                           parameter,
                           "the header puts the image's origin at " +
                             number_text(image.offset[d]) + " mm along axis " +
                             std::to_string(d) +
                             "; expected a finite offset of at most " +
                             number_text(largest_offset_mm) + " mm");
    }
  } // namespace

  LabelledImage
  read_labelled_image(const std::string &file, const std::string &parameter)
  {
    auto fail = [&](const std::string &message) {
      return InputError(file, parameter, message);
    };
    if (!std::filesystem::is_regular_file(file) ||
        ::access(file.c_str(), R_OK) != 0)
      throw fail("cannot read the file; expected a labelled NIfTI image "
                 "(.nii or .nii.gz)");

    nifti_set_debug_level(0);
    std::unique_ptr<nifti_image, NiftiDeleter> nim;
    {
      // Some of libnifti's messages ("** ERROR: nifti_convert_n1hdr2nim:
      // bad dim[0]") ignore the debug level: the one line is ours.
      const SilencedStderr silenced;
      // The header first: the voxels it declares must fit the file (or,
      // compressed, half the machine's memory) before they are allocated.
      nim.reset(nifti_image_read(file.c_str(), 0));
      if (nim)
        check_declared_size(*nim, file, parameter);
      nim.reset(nifti_image_read(file.c_str(), 1));
    }
    if (!nim || nim->data == nullptr)
      throw fail("not a readable NIfTI image; expected a labelled NIfTI "
                 "image (.nii or .nii.gz)");
    std::array<double, 3> written;
    long long             nonfinite = -1;
    {
      const SilencedStderr silenced;
      written   = written_voxel_sizes(file);
      nonfinite = first_nonfinite_voxel(*nim);
    }
    if (nonfinite >= 0)
      throw fail("voxel (" + std::to_string(nonfinite % nim->nx) + ", " +
                 std::to_string((nonfinite / nim->nx) % nim->ny) + ", " +
                 std::to_string(nonfinite / (nim->nx * nim->ny)) +
                 ") holds a value that is not a finite number; expected "
                 "whole-number labels");
    if (nim->nx < 2 || nim->ny < 2 || nim->nz < 2 || nim->nt > 1 || nim->nu > 1)
      throw fail("the image has dimensions " + std::to_string(nim->nx) + "x" +
                 std::to_string(nim->ny) + "x" + std::to_string(nim->nz) + "x" +
                 std::to_string(nim->nt) +
                 "; expected a 3d volume of at least 2x2x2 voxels");

    const std::size_t   n = nim->nvox;
    std::vector<double> values;
    switch (nim->datatype)
      {
        case DT_UINT8:
          convert<std::uint8_t>(nim->data, n, values);
          break;
        case DT_INT8:
          convert<std::int8_t>(nim->data, n, values);
          break;
        case DT_UINT16:
          convert<std::uint16_t>(nim->data, n, values);
          break;
        case DT_INT16:
          convert<std::int16_t>(nim->data, n, values);
          break;
        case DT_UINT32:
          convert<std::uint32_t>(nim->data, n, values);
          break;
        case DT_INT32:
          convert<std::int32_t>(nim->data, n, values);
          break;
        case DT_FLOAT32:
          convert<float>(nim->data, n, values);
          break;
        case DT_FLOAT64:
          convert<double>(nim->data, n, values);
          break;
        default:
          throw fail(std::string("unsupported voxel type ") +
                     nifti_datatype_string(nim->datatype) +
                     "; expected integer labels (uint8, int16, ...)");
      }
    const bool scaled =
      nim->scl_slope != 0 && (nim->scl_slope != 1 || nim->scl_inter != 0);

    LabelledImage image;
    image.size = {{static_cast<unsigned int>(nim->nx),
                   static_cast<unsigned int>(nim->ny),
                   static_cast<unsigned int>(nim->nz)}};
    image.labels.resize(n);
    for (std::size_t v = 0; v < n; ++v)
      {
        const double value =
          scaled ? nim->scl_slope * values[v] + nim->scl_inter : values[v];
        if (!(value >= 0 && value <= max_image_label &&
              value == std::round(value)))
          throw fail("voxel (" + std::to_string(v % nim->nx) + ", " +
                     std::to_string((v / nim->nx) % nim->ny) + ", " +
                     std::to_string(v / (std::size_t(nim->nx) * nim->ny)) +
                     ") holds " + number_text(value) +
                     "; expected whole-number labels from 0 (background) "
                     "to " +
                     std::to_string(max_image_label));
        image.labels[v] = static_cast<ImageLabel>(value);
      }

    const nifti_dmat44 *map = nullptr;
    if (nim->sform_code > 0)
      {
        map              = &nim->sto_xyz;
        image.xform_code = nim->sform_code;
      }
    else if (nim->qform_code > 0)
      {
        map              = &nim->qto_xyz;
        image.xform_code = nim->qform_code;
      }
    // libnifti makes a voxel size of 0 (or NaN) a 1 mm one: the header's
    // own sizes are checked wherever the sform does not replace them.
    if (nim->sform_code <= 0)
      for (unsigned int d = 0; d < 3; ++d)
        {
          const double h = written[d];
          if (!(std::abs(h) > 0) || !std::isfinite(h))
            throw fail("voxel size pixdim[" + std::to_string(d + 1) +
                       "] = " + number_text(h) +
                       " in the header; expected positive voxel sizes in "
                       "mm");
        }
    for (unsigned int r = 0; r < 3; ++r)
      {
        for (unsigned int c = 0; c < 3; ++c)
          image.index_to_mm[r][c] =
            map ? map->m[r][c] : (r == c ? std::abs((&nim->dx)[r]) : 0.);
        image.offset[r] = map ? map->m[r][3] : 0.;
      }
    const double det = dealii::determinant(image.index_to_mm);
    if (!(std::abs(det) > 0) || !std::isfinite(det))
      throw fail("the voxel-to-millimetre map of the header is singular; "
                 "expected positive voxel sizes");
    check_geometry(image, file, parameter);
    if (image.label_counts().empty())
      throw fail("the image holds no label (every voxel is 0); expected "
                 "labelled tissue (labels > 0)");
    return image;
  }

  void
  write_labelled_image(const LabelledImage &image,
                       const std::string   &file,
                       const std::string   &parameter)
  {
    const int64_t dims[8] = {
      3, image.size[0], image.size[1], image.size[2], 1, 1, 1, 1};
    nifti_set_debug_level(0);
    const unsigned int                         bytes = image.label_bytes();
    std::unique_ptr<nifti_image, NiftiDeleter> nim(
      nifti_make_new_nim(dims,
                         bytes == 1 ? DT_UINT8 :
                         bytes == 2 ? DT_UINT16 :
                                      DT_UINT32,
                         1));
    if (!nim)
      throw InputError(file, parameter, "cannot allocate the image");
    image.store_labels(nim->data);
    nim->nifti_type = NIFTI_FTYPE_NIFTI1_1;
    const auto h    = image.spacing();
    nim->dx = nim->pixdim[1] = h[0];
    nim->dy = nim->pixdim[2] = h[1];
    nim->dz = nim->pixdim[3] = h[2];
    nim->xyz_units           = NIFTI_UNITS_MM;
    nim->sform_code          = image.xform_code;
    nim->qform_code          = 0;
    for (unsigned int r = 0; r < 4; ++r)
      for (unsigned int c = 0; c < 4; ++c)
        nim->sto_xyz.m[r][c] =
          r == 3 ? (c == 3 ? 1. : 0.) :
                   (c == 3 ? image.offset[r] : image.index_to_mm[r][c]);
    nim->sto_ijk           = nifti_dmat44_inverse(nim->sto_xyz);
    const std::string name = file;
    if (!(name.size() > 4 && name.compare(name.size() - 4, 4, ".nii") == 0) &&
        !(name.size() > 7 && name.compare(name.size() - 7, 7, ".nii.gz") == 0))
      throw InputError(
        file,
        parameter,
        "unsupported file name; expected a name ending in .nii or .nii.gz");
    write_named_file_atomically(
      file,
      [&](const std::string &tmp) {
        if (nifti_set_filenames(nim.get(), tmp.c_str(), 0, 1) != 0)
          return false;
        nifti_image_write(nim.get());
        return true;
      },
      parameter,
      "cannot write the image; expected a writable location");
  }
} // namespace RestShape
