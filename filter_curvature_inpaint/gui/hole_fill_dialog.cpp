#include "hole_fill_dialog.h"

#include "pipeline/fill_one_hole.h"
#include "pipeline/fill_settings.h"
#include "pipeline/pipeline.h"
#include "report/hole_report.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QToolButton>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPainter>
#include <QPointer>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSettings>
#include <QSpinBox>
#include <QThread>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <utility>

namespace curvature_inpaint {

namespace {

constexpr int kThumbnail = 160;

// vcg::CallBackPos is a plain function pointer: the running worker's dialog and cancel flag
// live here. The dialog is modal and runs one worker at a time.
QPointer<HoleFillDialog> g_worker_dialog;
std::shared_ptr<std::atomic<bool>> g_worker_cancel;
QProgressBar* g_worker_progress = nullptr;
QLabel* g_worker_status = nullptr;

bool WorkerProgress(const int pos, const char* text) {
  const QString message = QString::fromUtf8(text);
  if (g_worker_dialog)
    QMetaObject::invokeMethod(
        g_worker_dialog.data(),
        [pos, message] {
          if (g_worker_progress) g_worker_progress->setValue(pos);
          if (g_worker_status) g_worker_status->setText(message);
        },
        Qt::QueuedConnection);
  return !(g_worker_cancel && *g_worker_cancel);
}

/// The coarse curvature image with the hole's border drawn in white.
QImage Outlined(const QImage& image, const QImage& mask) {
  QImage out = image.convertToFormat(QImage::Format_RGB32);
  auto hole = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < mask.width() && y < mask.height() &&
           qGray(mask.pixel(x, y)) > 127;
  };
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x)
      if (hole(x, y) && (!hole(x + 1, y) || !hole(x - 1, y) || !hole(x, y + 1) || !hole(x, y - 1)))
        for (int d = 0; d < 2; ++d)
          if (x + d < out.width()) out.setPixel(x + d, y, qRgb(255, 255, 255));
  return out;
}

QPixmap Thumbnail(const QImage& image) {
  return QPixmap::fromImage(
      image.scaled(kThumbnail, kThumbnail, Qt::KeepAspectRatio, Qt::SmoothTransformation));
}

QString Key(const QString& backend, const char* field) {
  return backend + "/" + field;
}

/// The backend the list shows (its items are InpaintBackends(), in order).
Backend SelectedBackend(const QComboBox& list) {
  return BackendAt(list.currentIndex());
}

/// A setting's tooltip (pipeline/fill_settings.h), which it returns, and for a number box the
/// range the setting may take.
QString Declare(QWidget* field, Setting id) {
  const SettingSpec& s = SettingOf(id);
  if (auto* box = qobject_cast<QSpinBox*>(field))
    box->setRange(int(s.min), int(std::min<double>(s.max, std::numeric_limits<int>::max())));
  if (auto* box = qobject_cast<QDoubleSpinBox*>(field)) box->setRange(s.min, s.max);
  const QString help = QString::fromStdString(SettingHelp(s));
  field->setToolTip(help);
  return help;
}

/// Where a list item keeps the variations it stands for (0-based, first and last).
constexpr int kFirstVariation = Qt::UserRole + 1;
constexpr int kLastVariation = Qt::UserRole + 2;

/// The validation candidate a variation was tried as: its kind, or for the inpainted
/// continuations the detail amplitude they have; -1 where it was not tried.
int CandidateOf(const HoleVariations& hv, FillKind kind) {
  const std::string name =
      TriedFillName({kind, kind == FillKind::kContinuation ? hv.detail : -1.0});
  const std::vector<TriedFill>& candidates = hv.choice.validation.candidates;
  for (size_t c = 0; c < candidates.size(); ++c)
    if (candidates[c].kind == kind && TriedFillName(candidates[c]) == name) return int(c);
  return -1;
}

/// An item's caption: its numbers and kind, and where the hole was validated how the kind did
/// on the test cuts, in words ("5: tri-laplacian (auto)\nbetter than the smooth fill on 6 of 6
/// test cuts").
QString Caption(const HoleVariations& hv, const VariationRun& g, bool automatic) {
  QString caption = g.first == g.last ? QString::number(g.first + 1)
                                      : QString("%1-%2").arg(g.first + 1).arg(g.last + 1);
  caption += ": " + QString(FillKindName(g.kind)) + (automatic ? " (auto)" : "");
  const int c = CandidateOf(hv, g.kind);
  if (c >= 0) {
    const std::string words = TestCutsInWords(hv.choice.validation, size_t(c));
    if (!words.empty()) caption += "\n" + QString::fromStdString(words);
  }
  return caption;
}

/// A list item for a run of variations (`best`: the automatic pick, 0-based): its picture, its
/// caption, the variations it stands for, and for a mirror image how far to trust it.
QListWidgetItem* VariationItem(const HoleVariations& hv, const VariationRun& group, int best) {
  // The same picture when selected: the selection shows as the frame and the bold label,
  // not as a tint that would make the variation look different.
  const QImage& image = hv.variations[size_t(group.first)];
  QIcon icon;
  icon.addPixmap(Thumbnail(image), QIcon::Normal);
  icon.addPixmap(Thumbnail(image), QIcon::Selected);
  const bool automatic = group.first <= best && best <= group.last;
  auto* item = new QListWidgetItem(icon, Caption(hv, group, automatic));
  item->setData(Qt::UserRole, QString(FillKindName(group.kind)));
  item->setData(kFirstVariation, group.first);
  item->setData(kLastVariation, group.last);
  // How far to trust a mirror image: how much of the fill it covers and how far the two
  // halves differ around the hole.
  const bool mirrored =
      group.kind == FillKind::kSymmetry || group.kind == FillKind::kSymmetrySurface;
  if (mirrored && hv.choice.priors.mirror_covered >= 0)
    item->setToolTip(QString("From the object's mirror image, which covers %1 % of the fill; "
                             "around the hole the two halves differ by %2 % of its radius.")
                         .arg(std::lround(100 * hv.choice.priors.mirror_covered))
                         .arg(100 * hv.choice.priors.mirror_ring_residual, 0, 'f', 1));
  if (automatic) {
    QFont f = item->font();
    f.setBold(true);
    item->setFont(f);
  }
  return item;
}

/// The list row that shows variation `j` (0-based).
int RowOf(const QListWidget* list, int j) {
  for (int row = 0; row < list->count(); ++row)
    if (list->item(row)->data(kFirstVariation).toInt() <= j &&
        j <= list->item(row)->data(kLastVariation).toInt())
      return row;
  return -1;
}

} // namespace

HoleFillDialog::HoleFillDialog(const CMeshO& mesh, QWidget* parent)
    : QDialog(parent), mesh_(mesh), cancel_requested_(std::make_shared<std::atomic<bool>>(false)) {
  setWindowTitle("Curvature Inpaint Hole Fill");
  setObjectName("curvatureInpaintDialog");
  resize(1000, 940);
  auto* form = new QFormLayout;
  QPushButton* reset = AddServiceRows(form);
  AddChoiceRows(form);
  AddHoleSelectionRows(form);
  auto* settings = new QGroupBox("Settings");
  auto* settings_column = new QVBoxLayout(settings);
  settings_column->addLayout(form);
  AddAdvancedSettings(settings_column);
  status_ = new QLabel;
  status_->setObjectName("status");
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(settings);
  layout->addLayout(MakeButtons());
  layout->addWidget(status_);
  layout->addWidget(MakeHoleList(), 1);

  LoadSettings();
  connect(backend_, &QComboBox::currentTextChanged, this, &HoleFillDialog::BackendChanged);
  connect(reset, &QPushButton::clicked, this, &HoleFillDialog::ResetPrompts);
  connect(inpaint_, &QPushButton::clicked, this, &HoleFillDialog::Inpaint);
  connect(cancel_, &QPushButton::clicked, this, &HoleFillDialog::CancelOrClose);
  connect(apply_, &QPushButton::clicked, this, &QDialog::accept);
}

QPushButton* HoleFillDialog::AddServiceRows(QFormLayout* form) {

  backend_ = new QComboBox;
  backend_->setObjectName("backend");
  for (const std::string& name : SettingChoices(Setting::kBackend))
    backend_->addItem(QString::fromStdString(name));
  Declare(backend_, Setting::kBackend);
  form->addRow("&Backend", backend_);
  url_ = new QLineEdit;
  url_->setObjectName("url");
  Declare(url_, Setting::kServerUrl);
  form->addRow("Server &URL", url_);
  model_ = new QLineEdit;
  model_->setObjectName("model");
  Declare(model_, Setting::kModel);
  form->addRow("&Model", model_);
  key_ = new QLabel;
  key_->setObjectName("keyStatus");
  key_->setWordWrap(true);
  form->addRow("API key", key_);
  prompt_ = new QLineEdit;
  prompt_->setObjectName("prompt");
  Declare(prompt_, Setting::kPrompt);
  form->addRow("&Prompt", prompt_);
  negative_prompt_ = new QLineEdit;
  negative_prompt_->setObjectName("negativePrompt");
  negative_prompt_->setToolTip("Stable Diffusion backends: what the image should not show.");
  form->addRow("&Negative prompt", negative_prompt_);
  auto* reset = new QPushButton("&Reset prompts");
  reset->setObjectName("resetPrompts");
  reset->setToolTip("The backend's default prompt, URL and model.");
  form->addRow("", reset);
  return reset;
}

void HoleFillDialog::AddChoiceRows(QFormLayout* form) {
  variations_ = new QSpinBox;
  variations_->setObjectName("variations");
  Declare(variations_, Setting::kVariations);
  form->addRow("&Variations", variations_);
  fake_holes_ = new QSpinBox;
  fake_holes_->setObjectName("fakeHoles");
  Declare(fake_holes_, Setting::kFakeHoles);
  form->addRow("&Fake holes per hole", fake_holes_);
  detail_ = new QDoubleSpinBox;
  detail_->setObjectName("detail");
  detail_->setSingleStep(0.25);
  Declare(detail_, Setting::kDetail);
  form->addRow("&Detail", detail_);
  symmetry_ = new QCheckBox("Offer each hole's mirror image");
  symmetry_->setObjectName("symmetry");
  Declare(symmetry_, Setting::kSymmetry);
  form->addRow("S&ymmetry", symmetry_);
  exemplar_ = new QCheckBox("Offer exemplar variations");
  exemplar_->setObjectName("exemplar");
  Declare(exemplar_, Setting::kExemplar);
  form->addRow("E&xemplar", exemplar_);
  learned_ = new QCheckBox("Offer the learned inpainter's fill");
  learned_->setObjectName("learned");
  Declare(learned_, Setting::kLearned);
  form->addRow("Lear&ned", learned_);
  creases_ = new QCheckBox("Carry creases across holes");
  creases_->setObjectName("creases");
  Declare(creases_, Setting::kCreases);
  form->addRow("&Creases", creases_);
  tri_laplacian_ = new QCheckBox("Continue the curvature");
  tri_laplacian_->setObjectName("triLaplacian");
  Declare(tri_laplacian_, Setting::kTriLaplacian);
  form->addRow("Tri-&Laplacian", tri_laplacian_);
}

void HoleFillDialog::AddAdvancedSettings(QVBoxLayout* column) {
  // The settings few people need, folded away: each with a line that says what it does.
  auto* advanced_form = new QFormLayout;
  auto add_advanced = [advanced_form](const QString& label, QWidget* field, Setting id) {
    const QString line = Declare(field, id);
    auto* explained = new QWidget;
    auto* column = new QVBoxLayout(explained);
    column->setContentsMargins(0, 0, 0, 0);
    column->addWidget(field);
    auto* note = new QLabel(line);
    note->setWordWrap(true);
    note->setEnabled(false); // greyed: an explanation, not a value
    column->addWidget(note);
    advanced_form->addRow(label, explained);
  };
  mode_ = new QComboBox;
  mode_->setObjectName("mode");
  for (const std::string& name : SettingChoices(Setting::kMode))
    mode_->addItem(QString::fromStdString(name));
  add_advanced("M&ode", mode_, Setting::kMode);
  similitude_ = new QDoubleSpinBox;
  similitude_->setObjectName("similitude");
  add_advanced("&Similitude", similitude_, Setting::kSimilitude);
  transformation_constant_ = new QLineEdit;
  transformation_constant_->setObjectName("transformationConstant");
  add_advanced("&Transformation constant", transformation_constant_,
               Setting::kTransformationConstant);
  image_size_ = new QSpinBox;
  image_size_->setObjectName("imageSize");
  image_size_->setSingleStep(64);
  image_size_->setSuffix(" px");
  add_advanced("Image si&ze", image_size_, Setting::kImageSize);
  auto* advanced = new QWidget;
  advanced->setObjectName("advancedSettings");
  advanced->setLayout(advanced_form);
  advanced->setVisible(false);
  auto* advanced_toggle = new QToolButton;
  advanced_toggle->setObjectName("advanced");
  advanced_toggle->setText("Advanced");
  advanced_toggle->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  advanced_toggle->setArrowType(Qt::RightArrow);
  advanced_toggle->setCheckable(true);
  advanced_toggle->setAutoRaise(true);
  connect(advanced_toggle, &QToolButton::toggled, this, [advanced, advanced_toggle](bool open) {
    advanced->setVisible(open);
    advanced_toggle->setArrowType(open ? Qt::DownArrow : Qt::RightArrow);
  });
  column->addWidget(advanced_toggle);
  column->addWidget(advanced);
}

void HoleFillDialog::AddHoleSelectionRows(QFormLayout* form) {
  max_hole_edges_ = new QSpinBox;
  max_hole_edges_->setObjectName("maxHoleEdges");
  Declare(max_hole_edges_, Setting::kMaxHoleSize);
  max_hole_edges_->setSpecialValueText("any size");
  form->addRow("Maximum hole size (edges)", max_hole_edges_);
  keep_longest_open_ = new QCheckBox("leave the longest border open (an open scan's edge)");
  keep_longest_open_->setObjectName("keepLongestOpen");
  Declare(keep_longest_open_, Setting::kKeepLongestOpen);
  form->addRow("Outer border", keep_longest_open_);
  selected_only_ = new QCheckBox("only holes beside selected faces");
  selected_only_->setObjectName("selectedOnly");
  Declare(selected_only_, Setting::kSelected);
  form->addRow("Selection", selected_only_);
}

QHBoxLayout* HoleFillDialog::MakeButtons() {
  inpaint_ = new QPushButton("&Inpaint");
  inpaint_->setObjectName("inpaint");
  inpaint_->setToolTip("Fill coarsely, paint the curvature images and inpaint them (the mesh "
                       "is not changed).");
  apply_ = new QPushButton("&Apply");
  apply_->setObjectName("apply");
  apply_->setEnabled(false);
  apply_->setToolTip("Deform every hole to its chosen variation and change the mesh.");
  cancel_ = new QPushButton("Cancel");
  cancel_->setObjectName("cancel");
  cancel_->setToolTip("Stop the running step, or close without changing the mesh.");
  progress_ = new QProgressBar;
  progress_->setObjectName("progress");
  progress_->setRange(0, 100);
  progress_->setValue(0);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(inpaint_);
  buttons->addWidget(progress_, 1);
  buttons->addWidget(apply_);
  buttons->addWidget(cancel_);
  return buttons;
}

QScrollArea* HoleFillDialog::MakeHoleList() {
  auto* holes = new QWidget;
  holes_layout_ = new QVBoxLayout(holes);
  holes_layout_->addStretch(1);
  auto* scroll = new QScrollArea;
  scroll->setWidget(holes);
  scroll->setWidgetResizable(true);
  scroll->setMinimumSize(4 * (kThumbnail + 24) + 2 * kThumbnail, kThumbnail + 120);
  return scroll;
}

HoleFillDialog::~HoleFillDialog() {
  if (worker_) {
    *cancel_requested_ = true;
    worker_->wait();
  }
}

HoleFillParams HoleFillDialog::Params() const {
  HoleFillParams p;
  p.inpaint.backend = SelectedBackend(*backend_);
  p.inpaint.url = url_->text().trimmed().toStdString();
  p.inpaint.model = model_->text().trimmed().toStdString();
  p.inpaint.prompt = prompt_->text().toStdString();
  p.inpaint.negative_prompt = negative_prompt_->text().toStdString();
  p.inpaint.variations = variations_->value();
  p.validation.fake_holes = fake_holes_->value();
  p.inpaint.detail = detail_->value();
  p.symmetry.enabled = symmetry_->isChecked();
  p.exemplar = exemplar_->isChecked();
  p.learned = learned_->isChecked();
  p.creases = creases_->isChecked();
  p.tri_laplacian = tri_laplacian_->isChecked();
  p.paper.similitude = similitude_->value();
  bool ok = false;
  const double tc = transformation_constant_->text().toDouble(&ok);
  // Text that is not a number reaches the parameter check, which names the field.
  p.paper.transformation_constant = ok ? tc : std::numeric_limits<double>::quiet_NaN();
  DeformationModeFromName(mode_->currentText().toStdString(), &p.mode);
  p.images.coarse.max_hole_edges = max_hole_edges_->value();
  p.images.coarse.selected_only = selected_only_->isChecked();
  p.images.coarse.keep_longest_open = keep_longest_open_->isChecked();
  p.images.image_size = image_size_->value();
  return p;
}

void HoleFillDialog::BackendChanged() {
  const QString backend = backend_->currentText();
  QSettings s("curvature-inpaint", "hole-fill");
  // Each backend keeps its own URL, model and prompts while the person switches between them.
  if (!backend_shown_.isEmpty()) {
    s.setValue(Key(backend_shown_, "url"), url_->text());
    s.setValue(Key(backend_shown_, "model"), model_->text());
    s.setValue(Key(backend_shown_, "prompt"), prompt_->text());
    s.setValue(Key(backend_shown_, "negative_prompt"), negative_prompt_->text());
  }
  backend_shown_ = backend;
  const BackendInfo& info = DescribeBackend(SelectedBackend(*backend_));
  url_->setText(s.value(Key(backend, "url")).toString());
  url_->setPlaceholderText(QString::fromStdString(info.default_url));
  url_->setEnabled(info.remote);
  model_->setText(s.value(Key(backend, "model")).toString());
  model_->setPlaceholderText(QString::fromStdString(info.default_model));
  model_->setEnabled(!info.default_model.empty());
  prompt_->setText(s.value(Key(backend, "prompt"),
                           QString::fromStdString(DefaultPrompt(SelectedBackend(*backend_))))
                       .toString());
  prompt_->setEnabled(info.remote);
  negative_prompt_->setText(s.value(Key(backend, "negative_prompt")).toString());
  negative_prompt_->setEnabled(info.negative_prompt);
  const QString var = QString::fromStdString(info.key_variable);
  if (var.isEmpty()) {
    key_->setText("none needed");
    key_->setStyleSheet("");
  } else if (std::getenv(info.key_variable.c_str()) && *std::getenv(info.key_variable.c_str())) {
    key_->setText("from the environment variable " + var + " (set)");
    key_->setStyleSheet("");
  } else {
    key_->setText(QString("Warning: %1 is not set%2. Set it in the environment MeshLab starts "
                          "from; keys are never stored.")
                      .arg(var, info.key_required ? ": the service will refuse" : ""));
    key_->setStyleSheet("color: #c03000; font-weight: bold");
  }
  key_->setProperty("missingKey", !var.isEmpty() && !(std::getenv(info.key_variable.c_str()) &&
                                                      *std::getenv(info.key_variable.c_str())));
}

void HoleFillDialog::ResetPrompts() {
  prompt_->setText(QString::fromStdString(DefaultPrompt(SelectedBackend(*backend_))));
  negative_prompt_->clear();
  url_->clear();
  model_->clear();
}

void HoleFillDialog::LoadSettings() {
  QSettings s("curvature-inpaint", "hole-fill");
  const int b = backend_->findText(s.value("backend", "embedded").toString());
  backend_->setCurrentIndex(b < 0 ? 0 : b);
  // What the user chose last, else the defaults every surface starts from.
  const HoleFillParams d = DefaultSettings();
  variations_->setValue(s.value("variations", d.inpaint.variations).toInt());
  fake_holes_->setValue(s.value("fake_holes", d.validation.fake_holes).toInt());
  detail_->setValue(s.value("detail", d.inpaint.detail).toDouble());
  symmetry_->setChecked(s.value("symmetry", d.symmetry.enabled).toBool());
  exemplar_->setChecked(s.value("exemplar", d.exemplar).toBool());
  learned_->setChecked(s.value("learned", d.learned).toBool());
  creases_->setChecked(s.value("creases", d.creases).toBool());
  tri_laplacian_->setChecked(s.value("triLaplacian", d.tri_laplacian).toBool());
  similitude_->setValue(s.value("similitude", d.paper.similitude).toDouble());
  transformation_constant_->setText(
      s.value("transformation_constant", QString::number(d.paper.transformation_constant))
          .toString());
  const int m = mode_->findText(s.value("mode", DeformationModeName(d.mode)).toString());
  mode_->setCurrentIndex(m < 0 ? 0 : m);
  image_size_->setValue(s.value("image_size", d.images.image_size).toInt());
  max_hole_edges_->setValue(s.value("max_hole_edges", d.images.coarse.max_hole_edges).toInt());
  selected_only_->setChecked(s.value("selected_only", d.images.coarse.selected_only).toBool());
  keep_longest_open_->setChecked(
      s.value("keep_longest_open", d.images.coarse.keep_longest_open).toBool());
  BackendChanged();
}

void HoleFillDialog::SaveSettings() const {
  QSettings s("curvature-inpaint", "hole-fill");
  const QString backend = backend_->currentText();
  s.setValue("backend", backend);
  s.setValue(Key(backend, "url"), url_->text());
  s.setValue(Key(backend, "model"), model_->text());
  s.setValue(Key(backend, "prompt"), prompt_->text());
  s.setValue(Key(backend, "negative_prompt"), negative_prompt_->text());
  s.setValue("variations", variations_->value());
  s.setValue("fake_holes", fake_holes_->value());
  s.setValue("detail", detail_->value());
  s.setValue("symmetry", symmetry_->isChecked());
  s.setValue("exemplar", exemplar_->isChecked());
  s.setValue("learned", learned_->isChecked());
  s.setValue("creases", creases_->isChecked());
  s.setValue("triLaplacian", tri_laplacian_->isChecked());
  s.setValue("similitude", similitude_->value());
  s.setValue("transformation_constant", transformation_constant_->text());
  s.setValue("mode", mode_->currentText());
  s.setValue("image_size", image_size_->value());
  s.setValue("max_hole_edges", max_hole_edges_->value());
  s.setValue("selected_only", selected_only_->isChecked());
  s.setValue("keep_longest_open", keep_longest_open_->isChecked());
}

void HoleFillDialog::SetBusy(bool busy) {
  inpaint_->setEnabled(!busy);
  apply_->setEnabled(!busy && !holes_.empty());
  for (auto* list : lists_) list->setEnabled(!busy);
  cancel_->setText(busy ? "Stop" : "Cancel");
  if (!busy) progress_->setValue(0);
}

void HoleFillDialog::RunWorker(std::function<void()> work, std::function<void()> done,
                               const QString& what) {
  if (worker_) return;
  *cancel_requested_ = false;
  g_worker_dialog = this;
  g_worker_cancel = cancel_requested_;
  g_worker_progress = progress_;
  g_worker_status = status_;
  status_->setText(what);
  SetBusy(true);
  auto error = std::make_shared<QString>();
  const auto cancel = cancel_requested_;
  worker_ = QThread::create([work = std::move(work), error, cancel] {
    try {
      work();
    } catch (const std::exception& e) {
      // A stop surfaces as CancelledError; an error the stop caused on its way out reads the same.
      *error = *cancel ? QString("Stopped.") : QString::fromStdString(e.what());
    }
  });
  connect(worker_, &QThread::finished, this, [this, error, done = std::move(done)] {
    worker_->deleteLater();
    worker_ = nullptr;
    g_worker_dialog = nullptr;
    g_worker_progress = nullptr;
    g_worker_status = nullptr;
    if (error->isEmpty()) done();
    SetBusy(false);
    ShowHoles();
    status_->setText(*error);
    emit WorkerFinished(*error);
  });
  worker_->start();
}

void HoleFillDialog::Inpaint() {
  SaveSettings();
  // The worker gets its own copy: the mesh is never touched from another thread.
  auto scratch = std::make_shared<CMeshO>();
  CopyMesh(mesh_, *scratch);
  const HoleFillParams params = Params();
  auto result = std::make_shared<std::vector<HoleVariations>>();
  holes_.clear();
  ShowHoles();
  RunWorker([scratch, params, result] { *result = InpaintHoles(*scratch, params, WorkerProgress); },
            [this, result] {
              holes_ = *result;
              rerolls_.assign(holes_.size(), 0);
            },
            "Inpainting...");
}

void HoleFillDialog::ReRoll(int hole) {
  if (hole < 0 || hole >= int(holes_.size()) || holes_[hole].image.isNull()) return;
  InpaintParams params = Params().inpaint;
  params.seed += 1000u * uint32_t(++rerolls_[hole]);
  auto copy = std::make_shared<HoleVariations>(holes_[hole]);
  RunWorker(
      [copy, params] {
        InpaintParams p = params;
        p.http.cancelled = [] { return !WorkerProgress(50, "Curvature Inpaint: re-rolling"); };
        InpaintAgain(*copy, p);
      },
      [this, hole, copy] {
        if (hole < int(holes_.size())) holes_[hole] = *copy;
      },
      QString("Re-rolling hole %1...").arg(hole + 1));
}

void HoleFillDialog::CancelOrClose() {
  if (worker_) {
    *cancel_requested_ = true;
    status_->setText("Stopping...");
    return;
  }
  QDialog::reject();
}

void HoleFillDialog::reject() {
  CancelOrClose();
}

void HoleFillDialog::done(int result) {
  SaveSettings();
  QDialog::done(result);
}

QVBoxLayout* HoleFillDialog::HoleControls(size_t k, QListWidget* list, bool coarse_chosen) {
  auto* side = new QVBoxLayout;
  auto* reroll = new QPushButton("Re-roll");
  reroll->setObjectName(QString("reroll_%1").arg(k + 1));
  reroll->setToolTip("Ask the backend for new variations of this hole.");
  connect(reroll, &QPushButton::clicked, this, [this, k] { ReRoll(int(k)); });
  auto* skip = new QCheckBox(coarse_chosen ? "Skip (auto)" : "Skip");
  skip->setObjectName(QString("skip_%1").arg(k + 1));
  skip->setToolTip("Leave this hole with its smooth coarse fill.");
  skip->setChecked(holes_[k].choice.pick == 0);
  // Choosing a variation undoes a skip (also the automatic one); skipping clears the choice.
  connect(list, &QListWidget::currentRowChanged, this, [this, k, skip, list](int row) {
    if (row < 0) return;
    holes_[k].choice.pick = list->item(row)->data(kFirstVariation).toInt() + 1;
    skip->setChecked(false);
  });
  connect(skip, &QCheckBox::toggled, this, [this, k, list](bool on) {
    if (on) {
      holes_[k].choice.pick = 0;
      list->setCurrentRow(-1);
    } else if (holes_[k].choice.pick == 0) {
      list->setCurrentRow(std::max(0, list->currentRow()));
      if (list->currentItem())
        holes_[k].choice.pick = list->currentItem()->data(kFirstVariation).toInt() + 1;
    }
  });
  side->addWidget(reroll);
  side->addWidget(skip);
  side->addStretch(1);
  return side;
}

void HoleFillDialog::ShowHoles() {
  while (holes_layout_->count() > 1) {
    QLayoutItem* item = holes_layout_->takeAt(0);
    delete item->widget();
    delete item;
  }
  lists_.clear();
  int ready = 0;
  for (size_t k = 0; k < holes_.size(); ++k) {
    HoleVariations& hv = holes_[k];
    auto* box = new QGroupBox(QString("Hole %1").arg(k + 1));
    box->setObjectName(QString("hole_%1").arg(k + 1));
    auto* column = new QVBoxLayout(box);
    auto* row = new QHBoxLayout;
    column->addLayout(row);
    const HoleChoice& choice = hv.choice;
    if (!choice.validation.candidates.empty() || !choice.validation.note.empty()) {
      // The choice in words; the test cuts' numbers for whoever wants them, in the tooltip.
      auto* validation =
          new QLabel("Automatic choice: " + QString::fromStdString(ChoiceInWords(choice)));
      validation->setObjectName(QString("validation_%1").arg(k + 1));
      validation->setWordWrap(true);
      validation->setToolTip(
          "Each way to fill this hole was tried on holes of its size cut into the known surface "
          "near it (test cuts); the automatic choice came clearly closest to the surface cut "
          "out, or else is the smooth fill.\n" +
          QString::fromStdString(DescribeValidation(choice.validation)));
      column->addWidget(validation);
    }
    if (!choice.problem.empty()) {
      row->addWidget(new QLabel(QString::fromStdString(choice.problem)));
      holes_layout_->insertWidget(holes_layout_->count() - 1, box);
      lists_.push_back(nullptr);
      continue;
    }
    ++ready;
    auto* coarse = new QLabel;
    coarse->setPixmap(Thumbnail(Outlined(hv.image, hv.mask)));
    coarse->setToolTip("The coarse fill's curvature; the hole is outlined.");
    row->addWidget(coarse);
    auto* list = new QListWidget;
    list->setObjectName(QString("variations_%1").arg(k + 1));
    list->setViewMode(QListView::IconMode);
    list->setIconSize(QSize(kThumbnail, kThumbnail));
    list->setFlow(QListView::LeftToRight);
    list->setWrapping(false);
    list->setMovement(QListView::Static);
    list->setMinimumHeight(kThumbnail + 48);
    list->setWordWrap(true);
    list->setGridSize(QSize(kThumbnail + 24, kThumbnail + 64));
    list->setMinimumHeight(kThumbnail + 80);
    // The automatic pick: the validated choice or the best-scored continuation, or none (Skip)
    // where the hole keeps the smooth fill.
    const int best = AutomaticPick(choice) - 1;
    const bool coarse_chosen = best < 0;
    for (const VariationRun& group : VariationRuns(hv)) {
      list->addItem(VariationItem(hv, group, best));
    }
    if (choice.pick > 0) list->setCurrentRow(RowOf(list, choice.pick - 1));
    connect(list, &QListWidget::itemDoubleClicked, this, [this, k](QListWidgetItem* item) {
      const int j = item->data(kFirstVariation).toInt();
      const QImage& image = holes_[k].variations[size_t(j)];
      QDialog big(this);
      big.setWindowTitle(QString("Hole %1, variation %2").arg(k + 1).arg(j + 1));
      auto* label = new QLabel;
      label->setPixmap(QPixmap::fromImage(image.scaled(512, 512, Qt::KeepAspectRatio)));
      auto* l = new QVBoxLayout(&big);
      l->addWidget(label);
      big.exec();
    });
    row->addWidget(list, 1);
    QVBoxLayout* side = HoleControls(k, list, coarse_chosen);
    row->addLayout(side);
    holes_layout_->insertWidget(holes_layout_->count() - 1, box);
    lists_.push_back(list);
  }
  lists_.erase(std::remove(lists_.begin(), lists_.end(), nullptr), lists_.end());
  setWindowTitle(holes_.empty() ? QString("Curvature Inpaint Hole Fill")
                                : QString("Curvature Inpaint Hole Fill: %1 of %2 holes ready")
                                      .arg(ready)
                                      .arg(holes_.size()));
  apply_->setEnabled(!worker_ && !holes_.empty());
}

} // namespace curvature_inpaint
