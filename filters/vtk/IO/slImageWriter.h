#ifndef slImageWriter_h
#define slImageWriter_h
/**
 * @class   slImageWriter
 * @brief   Writes a 2D vtkImageData through OpenImageIO, all or nothing.
 *
 * The format follows the file name's extension (GetSupportedExtensions()).
 * Unsigned char scalars are written as 8-bit, float scalars as float
 * where the format allows it (EXR, HDR, TIFF) and quantised otherwise.
 * Row 0 of the vtkImageData is the bottom of the picture.
 *
 * OpenImageIO encodes the image in memory; ShadeLab then writes the bytes to
 * a temporary file beside the target, syncs it and renames it over the
 * target: a failure (a full disk included) never leaves a partial file nor
 * destroys an existing one. A failure is a vtkErrorMacro of one line naming
 * the file and the system's reason, and Write() returning false
 * (slCallOrThrow() gives the line back).
 *
 * @warning Only unsigned char and float scalars are written (others are an
 * error, not converted). Float images saved as PNG, JPEG, BMP, TGA or PPM
 * lose their range: values are clamped to [0, 1] and quantised to 8 bits.
 *
 * @sa slImageReader vtkWindowToImageFilter
 */

#include "ShadeLabIOModule.h"

#include <vtkImageAlgorithm.h>

#include <string>

class SHADELABIO_EXPORT slImageWriter : public vtkImageAlgorithm
{
public:
  static slImageWriter* New();
  vtkTypeMacro(slImageWriter, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to write.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /// Updates the input and writes it. True on success; false after
  /// vtkErrorMacro (also when the input's update failed).
  bool Write();

  /// True if slImageWriter writes files with the extension of @p fileName.
  static bool CanWriteFile(const char* fileName);

  /// The extensions it writes, space separated: ".png .jpg ...".
  static const char* GetSupportedExtensions();

protected:
  slImageWriter();
  ~slImageWriter() override;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slImageWriter(const slImageWriter&) = delete;
  void operator=(const slImageWriter&) = delete;

  /// Writes @p image to FileName. Throws shadelab::Error "FILE: problem".
  void WriteImage(vtkImageData* image);

  char* FileName = nullptr;
};

#endif
