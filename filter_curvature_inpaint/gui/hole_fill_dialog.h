// The dialog of "Curvature Inpaint Hole Fill" in the MeshLab GUI: backend, prompt and
// parameters; "Inpaint" runs stages 0-8 on a copy of the mesh in a worker thread; then every
// hole's variations are shown with their scores and the automatic pick, to choose, enlarge,
// re-roll or skip; "Apply" accepts the dialog, after which the caller deforms the mesh with
// FillHoles(mesh, Params(), cb, &Holes()). The dialog never changes the mesh.
//
// Settings persist in QSettings("curvature-inpaint", "hole-fill"); API keys are never stored:
// they stay in the environment, and the dialog only says whether they are set.
#pragma once

#include <QDialog>

#include <atomic>
#include <functional>
#include <memory>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QHBoxLayout;
class QLabel;
class QLineEdit;
class QListWidget;
class QProgressBar;
class QPushButton;
class QScrollArea;
class QSpinBox;
class QThread;
class QVBoxLayout;
// MeshLab's mesh and the pipeline's records, declared only: their headers are the heaviest of
// the project, and this one is compiled again for Qt's meta-objects.
class CMeshO;

namespace curvature_inpaint {

struct HoleFillParams;
struct HoleVariations;

class HoleFillDialog : public QDialog {
  Q_OBJECT

public:
  /// `mesh` is read (copied) when Inpaint is pressed and must outlive the dialog.
  explicit HoleFillDialog(const CMeshO& mesh, QWidget* parent = nullptr);
  ~HoleFillDialog() override;

  /// The parameters the widgets show.
  HoleFillParams Params() const;
  /// Every hole's variations with the person's choice (pick 0: keep the coarse fill).
  const std::vector<HoleVariations>& Holes() const { return holes_; }
  /// Whether a worker (inpaint or re-roll) is running.
  bool Busy() const { return worker_ != nullptr; }

public slots:
  void Inpaint();
  void ReRoll(int hole);
  /// Stops a running worker (also during a network call); otherwise rejects the dialog.
  void CancelOrClose();
  void ResetPrompts();

signals:
  /// A worker ended: with the holes updated, or with `error` set.
  void WorkerFinished(const QString& error);

protected:
  void reject() override;
  void done(int result) override; ///< keeps the settings, whether applied or cancelled

private:
  // The dialog's parts, built once by the constructor.
  /// The backend, its address, model, key status and prompts; returns the prompts' reset button.
  QPushButton* AddServiceRows(QFormLayout* form);
  /// Variations, fake holes, detail and the priors: what a hole's choice is made among.
  void AddChoiceRows(QFormLayout* form);
  /// The settings few people need, folded away under a toggle.
  void AddAdvancedSettings(QVBoxLayout* column);
  /// Which holes are filled.
  void AddHoleSelectionRows(QFormLayout* form);
  /// Inpaint, the progress bar, Apply and Cancel.
  QHBoxLayout* MakeButtons();
  /// The holes' variations, filled in by ShowHoles.
  QScrollArea* MakeHoleList();

  void BackendChanged();
  void LoadSettings();
  void SaveSettings() const;
  /// Runs `work` in a worker thread, then `done` on the GUI thread if it succeeded.
  void RunWorker(std::function<void()> work, std::function<void()> done, const QString& what);
  void ShowHoles();
  /// Hole k's Re-roll and Skip (`list`: its variations; `coarse_chosen`: Skip is automatic).
  QVBoxLayout* HoleControls(size_t k, QListWidget* list, bool coarse_chosen);
  void SetBusy(bool busy);

  const CMeshO& mesh_;
  std::vector<HoleVariations> holes_;
  std::vector<int> rerolls_;
  QString backend_shown_;

  QComboBox* backend_;
  QLineEdit* url_;
  QLineEdit* model_;
  QLabel* key_;
  QLineEdit* prompt_;
  QLineEdit* negative_prompt_;
  QSpinBox* variations_;
  QSpinBox* fake_holes_;
  QDoubleSpinBox* detail_;
  QCheckBox* symmetry_;
  QCheckBox* exemplar_;
  QCheckBox* learned_;
  QCheckBox* creases_;
  QCheckBox* tri_laplacian_;
  QDoubleSpinBox* similitude_;
  QLineEdit* transformation_constant_;
  QComboBox* mode_;
  QSpinBox* image_size_;
  QSpinBox* max_hole_edges_;
  QCheckBox* selected_only_;
  QCheckBox* keep_longest_open_;
  QPushButton* inpaint_;
  QPushButton* apply_;
  QPushButton* cancel_;
  QProgressBar* progress_;
  QLabel* status_;
  QVBoxLayout* holes_layout_;
  std::vector<QListWidget*> lists_;

  QThread* worker_ = nullptr;
  std::shared_ptr<std::atomic<bool>> cancel_requested_;
};

} // namespace curvature_inpaint
