#ifndef slImageReader_h
#define slImageReader_h
/**
 * @class   slImageReader
 * @brief   Reads any image OpenImageIO can read (PNG, JPEG, EXR, HDR, TIFF...).
 *
 * The output is a 2D vtkImageData whose point scalars ("ImageScalars") hold
 * the channels of the file: unsigned char for 8-bit files, float otherwise.
 * Rows are flipped so that row 0 is the bottom of the picture, as VTK and
 * texture coordinates expect.
 *
 * A missing, unreadable or corrupt file gives an error through vtkErrorMacro
 * (one line naming the file), an empty output and a failed update
 * (slUpdateOrThrow() gives the line back).
 *
 * @warning Only the first subimage is read (the first part of a multi-part
 * EXR, the first page of a TIFF). Integer images deeper than 8 bits (16-bit
 * PNG or TIFF) come out as float, normalised to [0, 1].
 *
 * @sa slImageWriter vtkTexture
 */

#include "ShadeLabIOModule.h"

#include <vtkImageAlgorithm.h>

#include <string>

class SHADELABIO_EXPORT slImageReader : public vtkImageAlgorithm
{
public:
  static slImageReader* New();
  vtkTypeMacro(slImageReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to read.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Convert every file to float scalars (linear values as stored). Off by default.
  vtkSetMacro(OutputFloat, bool);
  vtkGetMacro(OutputFloat, bool);
  vtkBooleanMacro(OutputFloat, bool);
  ///@}

protected:
  slImageReader();
  ~slImageReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slImageReader(const slImageReader&) = delete;
  void operator=(const slImageReader&) = delete;

  char* FileName = nullptr;
  bool OutputFloat = false;
};

#endif
