#ifndef shadelab_viewer_MaterialPanel_h
#define shadelab_viewer_MaterialPanel_h
/**
 * @class   MaterialPanel
 * @brief   Edits the scene's material live: one control per colour and number
 *          key of the material (shadelab::materialKeys(), the rows of
 *          SHADELAB_MATERIAL_PARAMETERS), of those the scene's model reads.
 *
 * Each row is built from its key: the key's name as the label, what it
 * means as the tooltip, a ColorButton over the key's range for a colour
 * (values above 1 are shown and kept), a NumberControl over the key's range
 * for a number. A row whose parameter the current model does
 * not read (its bit is not in the model row's `reads`) is hidden, so a new
 * material parameter or model needs no edit here. Every change goes to the
 * document at once as a MaterialChange, which the view turns into uniforms:
 * dragging a slider re-renders without rebuilding.
 *
 * The built-in parameters sit in one group box of a vertical layout, so
 * other sections (another kind of material) can be added below it.
 */

#include <QString>
#include <QWidget>

#include <vector>

class QFormLayout;

namespace shadelab
{
namespace viewer
{
class ColorButton;
class NumberControl;
class ViewerDocument;

class MaterialPanel : public QWidget
{
  Q_OBJECT
public:
  explicit MaterialPanel(ViewerDocument* document, QWidget* parent = nullptr);

  /// The control of material key @p key ("shininess", "roughness", ...), or
  /// null if the key is not a number (colour).
  NumberControl* numberControl(const QString& key) const;
  ColorButton* colourControl(const QString& key) const;
  /// The keys whose rows are shown for the scene's model, in table order.
  QStringList shownKeys() const;

private:
  struct Row
  {
    QString key;
    unsigned bit = 0;        ///< MaterialParameterBit
    int index = 0;           ///< in shadelab::materialKeys()
    QWidget* editor = nullptr;
    ColorButton* colour = nullptr;
    NumberControl* number = nullptr;
  };
  void showScene();

  ViewerDocument* Document;
  QFormLayout* Form;
  std::vector<Row> Rows;
};

} // namespace viewer
} // namespace shadelab

#endif
