// The hole-fill dialog with real widgets on Qt's offscreen platform: defaults per backend,
// persistence, the warning for a missing key, choosing and skipping variations, and cancel
// during a network call.
#include "cli/command_line.h"
#include "filter_table.h"
#include "hole_fill_dialog.h"
#include "pipeline/fill_settings.h"
#include "io/mesh_io.h"
#include "pipeline/hole_fill.h"
#include "pipeline/pipeline.h"
#include "symmetric_egg.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QTcpServer>
#include <QTcpSocket>
#include <QTemporaryDir>
#include <QToolButton>
#include <QtTest>

#include <cstdlib>
#include <memory>

using curvature_inpaint::FillKind;
using curvature_inpaint::HoleFillDialog;

namespace {

template <typename W>
W* Find(const QWidget& dialog, const char* name) {
  W* w = dialog.findChild<W*>(name);
  if (!w) qFatal("no widget %s", name);
  return w;
}

void ChooseBackend(HoleFillDialog& d, const char* backend) {
  auto* combo = Find<QComboBox>(d, "backend");
  combo->setCurrentIndex(combo->findText(backend));
}

} // namespace

class DialogTest : public QObject {
  Q_OBJECT

private:
  CMeshO mesh_;

private slots:
  void initTestCase() {
    curvature_inpaint::LoadMesh(std::string(CI_SOURCE_DIR) + "/meshes/sample_holes.ply", mesh_);
    QVERIFY(mesh_.vn > 0);
  }

  void init() { QSettings("curvature-inpaint", "hole-fill").clear(); }

  // Each setting of the hole fill is declared once (pipeline/fill_settings.h): MeshLab's filter
  // lists it with its help and the default, the dialog shows the same help as a tooltip, the
  // command line's help has its option with its line, and the range check refuses a value
  // past its end. A setting added to the table reaches all four, or this fails.
  void every_setting_reaches_the_filter_the_dialog_the_command_line_and_the_range_check() {
    using namespace curvature_inpaint;
    HoleFillDialog d(mesh_);
    const plugin::FilterSpec& filter = plugin::Filter(plugin::FilterId::kHoleFill);
    const cli::Command* fill = cli::FindCommand("fill");
    QVERIFY(fill);
    const HoleFillParams defaults = DefaultSettings();
    for (const SettingSpec& s : Settings()) {
      const std::string help = SettingHelp(s);
      bool in_filter = false;
      for (const plugin::ParamSpec& p : filter.params)
        if (p.name == s.script_name) {
          in_filter = p.help == help && p.label == s.label;
          const double value = SettingValue(s.id, defaults);
          if (p.type == plugin::ParamType::kBool)
            in_filter = in_filter && p.value.b == (value != 0);
          if (p.type == plugin::ParamType::kInt || p.type == plugin::ParamType::kEnum)
            in_filter = in_filter && p.value.i == int(value);
          if (p.type == plugin::ParamType::kFloat)
            in_filter = in_filter && p.value.f == float(value);
          if (p.type == plugin::ParamType::kString)
            in_filter = in_filter && p.value.s == SettingText(s.id, defaults);
        }
      QVERIFY2(in_filter, s.script_name);
      bool in_dialog = false;
      for (QWidget* w : d.findChildren<QWidget*>())
        in_dialog = in_dialog || w->toolTip() == QString::fromStdString(help);
      QVERIFY2(in_dialog, s.script_name);
      bool in_help = false;
      for (const cli::Option& o : fill->options)
        in_help = in_help || (o.name == std::string(s.option) && o.help == SettingBrief(s));
      QVERIFY2(in_help && cli::CommandHelp(*fill).find(s.option) != std::string::npos,
               s.script_name);
      if (s.type == SettingType::kBool || s.type == SettingType::kText) continue;
      HoleFillParams past = defaults;
      const double end = s.type == SettingType::kChoice ? double(SettingChoices(s.id).size())
                                                        : s.max + std::max(1.0, std::abs(s.max));
      SetSetting(s.id, end, past);
      bool refused = false;
      try {
        CheckHoleFillParams(past);
      } catch (const vcg_ext::InvalidParameterError& e) {
        refused = std::string(e.what()).find(s.what) != std::string::npos;
      }
      QVERIFY2(refused, s.script_name);
    }
  }

  void expert_settings_are_folded_away_with_a_line_each() {
    HoleFillDialog d(mesh_);
    d.show();
    auto* advanced = Find<QWidget>(d, "advancedSettings");
    QVERIFY(!advanced->isVisible());
    for (const char* name : {"mode", "similitude", "transformationConstant", "imageSize"}) {
      QWidget* field = Find<QWidget>(d, name);
      QVERIFY2(advanced->isAncestorOf(field), name);
      QVERIFY2(!field->toolTip().isEmpty(), name);
      // The explanation is on screen beside the field, not only in its tooltip.
      bool explained = false;
      for (QLabel* note : field->parentWidget()->findChildren<QLabel*>())
        explained = explained || note->text() == field->toolTip();
      QVERIFY2(explained, name);
    }
    for (const char* name : {"backend", "variations", "fakeHoles", "maxHoleEdges"})
      QVERIFY2(!advanced->isAncestorOf(Find<QWidget>(d, name)), name);
    Find<QToolButton>(d, "advanced")->click();
    QVERIFY(advanced->isVisible());
    Find<QSpinBox>(d, "imageSize")->setValue(256);
    QCOMPARE(d.Params().images.image_size, 256);
  }

  void defaults_per_backend() {
    HoleFillDialog d(mesh_);
    QCOMPARE(Find<QComboBox>(d, "backend")->currentText(), QString("embedded"));
    QCOMPARE(Find<QSpinBox>(d, "variations")->value(), 4);
    QCOMPARE(Find<QDoubleSpinBox>(d, "similitude")->value(), 30.0);
    QCOMPARE(Find<QLineEdit>(d, "transformationConstant")->text().toDouble(), 5e-5);
    QCOMPARE(Find<QComboBox>(d, "mode")->currentText(), QString("direct"));
    QCOMPARE(Find<QSpinBox>(d, "imageSize")->value(), 512);
    QCOMPARE(d.Params().images.image_size, 512);
    QVERIFY(!Find<QLineEdit>(d, "prompt")->isEnabled());

    ChooseBackend(d, "openai");
    QCOMPARE(Find<QLineEdit>(d, "prompt")->text(), QString("fill in the blanks"));
    QCOMPARE(Find<QLineEdit>(d, "url")->placeholderText(), QString("https://api.openai.com/v1"));
    QCOMPARE(Find<QLineEdit>(d, "model")->placeholderText(), QString("dall-e-2"));
    QVERIFY(!Find<QLineEdit>(d, "negativePrompt")->isEnabled());

    ChooseBackend(d, "sd-webui");
    QVERIFY(Find<QLineEdit>(d, "prompt")->text().startsWith("Color map representing curvatures"));
    QCOMPARE(Find<QLineEdit>(d, "url")->placeholderText(), QString("http://127.0.0.1:7860"));
    QVERIFY(Find<QLineEdit>(d, "negativePrompt")->isEnabled());

    // An edited prompt stays with its backend; Reset brings the default back.
    Find<QLineEdit>(d, "prompt")->setText("a relief");
    ChooseBackend(d, "openai");
    ChooseBackend(d, "sd-webui");
    QCOMPARE(Find<QLineEdit>(d, "prompt")->text(), QString("a relief"));
    Find<QPushButton>(d, "resetPrompts")->click();
    QVERIFY(Find<QLineEdit>(d, "prompt")->text().startsWith("Color map representing curvatures"));
    QVERIFY(d.Params().inpaint.backend == curvature_inpaint::Backend::kSdWebUi);
  }

  void settings_persist_but_keys_never() {
    qputenv("OPENAI_API_KEY", "sk-dialogtest-0123456789");
    {
      HoleFillDialog d(mesh_);
      ChooseBackend(d, "openai");
      Find<QLineEdit>(d, "url")->setText("http://127.0.0.1:9");
      Find<QLineEdit>(d, "prompt")->setText("a nose");
      Find<QSpinBox>(d, "variations")->setValue(3);
      Find<QDoubleSpinBox>(d, "similitude")->setValue(12);
      Find<QComboBox>(d, "mode")->setCurrentIndex(1);
      Find<QSpinBox>(d, "maxHoleEdges")->setValue(50);
      Find<QPushButton>(d, "cancel")->click(); // closing keeps the settings too
      QCOMPARE(d.result(), int(QDialog::Rejected));
    }
    HoleFillDialog d(mesh_);
    QCOMPARE(Find<QComboBox>(d, "backend")->currentText(), QString("openai"));
    QCOMPARE(Find<QLineEdit>(d, "url")->text(), QString("http://127.0.0.1:9"));
    QCOMPARE(Find<QLineEdit>(d, "prompt")->text(), QString("a nose"));
    QCOMPARE(Find<QSpinBox>(d, "variations")->value(), 3);
    QCOMPARE(Find<QDoubleSpinBox>(d, "similitude")->value(), 12.0);
    QCOMPARE(Find<QComboBox>(d, "mode")->currentText(), QString("paper"));
    QCOMPARE(d.Params().images.coarse.max_hole_edges, 50);
    QSettings settings("curvature-inpaint", "hole-fill");
    settings.sync();
    QFile file(settings.fileName());
    QVERIFY(file.open(QIODevice::ReadOnly));
    const QByteArray stored = file.readAll();
    QVERIFY(stored.contains("a nose"));
    QVERIFY(!stored.contains("sk-dialogtest"));
    QVERIFY(!Find<QLabel>(d, "keyStatus")->text().contains("sk-dialogtest"));
    qunsetenv("OPENAI_API_KEY");
  }

  void warns_when_the_key_is_missing() {
    qunsetenv("STABILITY_API_KEY");
    HoleFillDialog d(mesh_);
    ChooseBackend(d, "stability");
    auto* key = Find<QLabel>(d, "keyStatus");
    QVERIFY(key->property("missingKey").toBool());
    QVERIFY(key->text().contains("STABILITY_API_KEY is not set"));
    ChooseBackend(d, "embedded");
    QVERIFY(!key->property("missingKey").toBool());
    qputenv("STABILITY_API_KEY", "sk-another-0123456789");
    ChooseBackend(d, "stability");
    QVERIFY(!key->property("missingKey").toBool());
    QVERIFY(key->text().contains("(set)"));
    qunsetenv("STABILITY_API_KEY");
  }

  void inpaint_then_choose_and_skip_variations() {
    const int vertices = mesh_.vn;
    HoleFillDialog d(mesh_);
    d.show();
    Find<QSpinBox>(d, "variations")->setValue(3);
    QVERIFY(!Find<QPushButton>(d, "apply")->isEnabled());
    QTest::mouseClick(Find<QPushButton>(d, "inpaint"), Qt::LeftButton);
    QTRY_VERIFY_WITH_TIMEOUT(!d.Busy(), 120000);
    QCOMPARE(mesh_.vn, vertices); // the preview works on a copy
    QCOMPARE(int(d.Holes().size()), 3);
    for (const auto& hole : d.Holes()) {
      QVERIFY(hole.choice.problem.empty());
      // Three continuations, then the priors' variations where the hole has them.
      QVERIFY(hole.variations.size() >= 3);
      QCOMPARE(hole.choice.kinds.size(), hole.variations.size());
      for (size_t j = 0; j < 3; ++j) QVERIFY(hole.choice.kinds[j] == FillKind::kContinuation);
      // The automatic pick: Skip where the fake holes found the coarse fill closest, a prior's
      // variation where it validated best, else the best-scored continuation; the dialog
      // shows the validation.
      QVERIFY(!hole.choice.validation.candidates.empty());
      const curvature_inpaint::TriedFill& choice = hole.choice.validation.Chosen();
      const int best =
          int(std::max_element(hole.choice.scores.begin(), hole.choice.scores.begin() + 3) -
              hole.choice.scores.begin()) +
          1;
      if (choice.kind == FillKind::kCoarse)
        QCOMPARE(hole.choice.pick, 0);
      else if (choice.kind == FillKind::kContinuation)
        QCOMPARE(hole.choice.pick, best);
      else
        QVERIFY(hole.choice.kinds[size_t(hole.choice.pick - 1)] == choice.kind);
    }
    // The choice in words; the numbers only in the tooltip, and no score in any caption.
    const QString choice = Find<QLabel>(d, "validation_1")->text();
    QVERIFY2(choice.startsWith("Automatic choice: ") &&
                 choice.contains(QRegularExpression("(better than the smooth fill|best) on \\d of "
                                                    "\\d test cuts")),
             qPrintable(choice));
    QVERIFY(Find<QLabel>(d, "validation_1")->toolTip().contains("chose"));
    for (int k = 1; k <= 3; ++k) {
      auto* variations = Find<QListWidget>(d, qPrintable(QString("variations_%1").arg(k)));
      for (int row = 0; row < variations->count(); ++row)
        QVERIFY2(!variations->item(row)->text().contains(QRegularExpression("-?0\\.\\d{3}")),
                 qPrintable(variations->item(row)->text()));
    }
    QVERIFY(d.windowTitle().contains("3 of 3 holes ready"));
    QVERIFY(Find<QPushButton>(d, "apply")->isEnabled());

    // Click the last item of hole 1; skip hole 2.
    auto* list = Find<QListWidget>(d, "variations_1");
    QListWidgetItem* last = list->item(list->count() - 1);
    const int last_variation = last->data(Qt::UserRole + 1).toInt() + 1;
    QCOMPARE(last_variation, int(d.Holes()[0].variations.size()));
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, list->visualItemRect(last).center());
    QCOMPARE(d.Holes()[0].choice.pick, last_variation);
    Find<QCheckBox>(d, "skip_2")->click();
    QCOMPARE(d.Holes()[1].choice.pick, 0);
    // Hole 3: skipped, then a variation clicked: the click undoes the skip.
    auto* skip_3 = Find<QCheckBox>(d, "skip_3");
    if (!skip_3->isChecked()) skip_3->click();
    QCOMPARE(d.Holes()[2].choice.pick, 0);
    auto* list_3 = Find<QListWidget>(d, "variations_3");
    QTest::mouseClick(list_3->viewport(), Qt::LeftButton, {},
                      list_3->visualItemRect(list_3->item(1)).center());
    QCOMPARE(d.Holes()[2].choice.pick, list_3->item(1)->data(Qt::UserRole + 1).toInt() + 1);
    QVERIFY(!skip_3->isChecked());

    // Apply's input deforms a copy of the mesh as chosen: hole 2 keeps its coarse fill.
    CMeshO applied;
    curvature_inpaint::CopyMesh(mesh_, applied);
    const auto result = curvature_inpaint::FillHoles(applied, d.Params(), nullptr, &d.Holes());
    QCOMPARE(int(result.holes.size()), 3);
    QCOMPARE(result.holes[0].choice.pick, last_variation);
    QVERIFY(result.holes[1].choice.problem.find("skipped") != std::string::npos);
    QVERIFY(result.holes[2].choice.problem.empty());

    QTest::mouseClick(Find<QPushButton>(d, "apply"), Qt::LeftButton);
    QCOMPARE(d.result(), int(QDialog::Accepted));
  }

  void symmetry_variations_carry_their_kind_and_apply() {
    // A mirror-symmetric egg with a hole over one of its bumps.
    CMeshO egg;
    test::MakeSymmetricEgg(egg);
    const Eigen::Vector3d bump = test::EggBumps()[0];
    test::PunchBump(egg, bump);
    const size_t scan_vertices = egg.vert.size();
    HoleFillDialog d(egg);
    d.show();
    Find<QSpinBox>(d, "variations")->setValue(2);
    Find<QSpinBox>(d, "fakeHoles")->setValue(0); // the automatic pick is then a continuation
    QVERIFY(Find<QCheckBox>(d, "symmetry")->isChecked());
    QVERIFY(!Find<QCheckBox>(d, "exemplar")->isChecked()); // on request only
    Find<QCheckBox>(d, "exemplar")->setChecked(true);
    QVERIFY(!Find<QCheckBox>(d, "learned")->isChecked()); // on request only
    Find<QCheckBox>(d, "learned")->setChecked(true);
    d.Inpaint();
    QTRY_VERIFY_WITH_TIMEOUT(!d.Busy(), 120000);
    QCOMPARE(int(d.Holes().size()), 1);
    const auto& hole = d.Holes()[0];
    QVERIFY2(hole.choice.problem.empty(), hole.choice.problem.c_str());
    QVERIFY2(hole.choice.priors.no_symmetry.empty(), hole.choice.priors.no_symmetry.c_str());
    // The egg is smooth all round: the crease prior offers its one face extended too.
    QVERIFY(hole.choice.kinds ==
            (std::vector<FillKind>{FillKind::kContinuation, FillKind::kContinuation,
                                   FillKind::kExemplar, FillKind::kExemplar, FillKind::kLearned,
                                   FillKind::kTriLaplacian, FillKind::kSymmetry,
                                   FillKind::kSymmetrySurface, FillKind::kFace}));
    QVERIFY(hole.choice.kinds[size_t(hole.choice.pick - 1)] == FillKind::kContinuation);
    // Each item says its kind; the two continuations, identical at detail 0, are one item;
    // clicking the mirrored surface chooses it.
    auto* list = Find<QListWidget>(d, "variations_1");
    QCOMPARE(hole.variations[0], hole.variations[1]);
    QCOMPARE(list->count(), 8);
    QVERIFY2(list->item(0)->text().startsWith("1-2: continuation (auto)"),
             qPrintable(list->item(0)->text()));
    QVERIFY(list->item(1)->text().contains("exemplar"));
    QVERIFY(list->item(3)->text().contains("learned"));
    QVERIFY(list->item(4)->text().contains("tri-laplacian"));
    QVERIFY(list->item(5)->text().contains("symmetry"));
    QCOMPARE(list->item(6)->data(Qt::UserRole).toString(), QString("symmetry surface"));
    for (int row : {5, 6})
      QVERIFY2(list->item(row)->toolTip().contains("mirror image, which covers 100 % of the fill"),
               qPrintable(list->item(row)->toolTip()));
    QVERIFY(list->item(4)->toolTip().isEmpty());
    QVERIFY(list->item(7)->text().contains("face"));
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {},
                      list->visualItemRect(list->item(6)).center());
    QCOMPARE(d.Holes()[0].choice.pick, 8);
    // Apply's input: the hole takes the mirrored surface, bump and all.
    CMeshO applied;
    curvature_inpaint::CopyMesh(egg, applied);
    const auto result = curvature_inpaint::FillHoles(applied, d.Params(), nullptr, &d.Holes());
    QVERIFY(result.holes[0].kind == FillKind::kSymmetrySurface);
    QVERIFY(std::abs(test::FillHeight(applied, scan_vertices, bump) - test::kEggBump) <
            0.1 * test::kEggBump);
    // Unchecked, the preview offers the continuations alone.
    Find<QCheckBox>(d, "symmetry")->setChecked(false);
    Find<QCheckBox>(d, "exemplar")->setChecked(false);
    QVERIFY(Find<QCheckBox>(d, "learned")->isChecked());
    Find<QCheckBox>(d, "learned")->setChecked(false);
    Find<QCheckBox>(d, "triLaplacian")->setChecked(false);
    Find<QCheckBox>(d, "creases")->setChecked(false);
    d.Inpaint();
    QTRY_VERIFY_WITH_TIMEOUT(!d.Busy(), 120000);
    QVERIFY(d.Holes()[0].choice.kinds ==
            (std::vector<FillKind>{FillKind::kContinuation, FillKind::kContinuation}));
  }

  void reroll_replaces_one_hole() {
    HoleFillDialog d(mesh_);
    Find<QSpinBox>(d, "variations")->setValue(2);
    // A seed changes the continuations only where they carry detail.
    Find<QSpinBox>(d, "fakeHoles")->setValue(0);
    Find<QDoubleSpinBox>(d, "detail")->setValue(1);
    d.Inpaint();
    QTRY_VERIFY_WITH_TIMEOUT(!d.Busy(), 120000);
    const QImage before = d.Holes()[0].variations[0], other = d.Holes()[1].variations[0];
    Find<QPushButton>(d, "reroll_1")->click();
    QTRY_VERIFY_WITH_TIMEOUT(!d.Busy(), 120000);
    QVERIFY(d.Holes()[0].variations[0] != before);
    QVERIFY(d.Holes()[1].variations[0] == other);
  }

  void a_field_that_is_not_a_number_is_named() {
    HoleFillDialog d(mesh_);
    d.show();
    Find<QLineEdit>(d, "transformationConstant")->setText("fast");
    Find<QPushButton>(d, "inpaint")->click();
    QTRY_VERIFY_WITH_TIMEOUT(!d.Busy(), 60000);
    QVERIFY(d.Holes().empty());
    QVERIFY2(Find<QLabel>(d, "status")->text().contains("the transformation constant must be"),
             qPrintable(Find<QLabel>(d, "status")->text()));
    QVERIFY(!Find<QPushButton>(d, "apply")->isEnabled());
  }

  void cancel_stops_a_network_call_and_then_closes() {
    // A server that accepts the request and never answers.
    QTcpServer server;
    QVERIFY(server.listen(QHostAddress::LocalHost));
    std::vector<std::unique_ptr<QTcpSocket>> held;
    connect(&server, &QTcpServer::newConnection, [&] {
      while (server.hasPendingConnections()) held.emplace_back(server.nextPendingConnection());
    });
    HoleFillDialog d(mesh_);
    d.show();
    ChooseBackend(d, "comfyui");
    Find<QLineEdit>(d, "url")->setText(QString("http://127.0.0.1:%1").arg(server.serverPort()));
    Find<QPushButton>(d, "inpaint")->click();
    QVERIFY(d.Busy());
    QTRY_VERIFY_WITH_TIMEOUT(!held.empty(), 60000);
    Find<QPushButton>(d, "cancel")->click();
    QTRY_VERIFY_WITH_TIMEOUT(!d.Busy(), 60000);
    QVERIFY(d.isVisible()); // stopping the work does not close the dialog
    QVERIFY(d.Holes().empty());
    QCOMPARE(Find<QLabel>(d, "status")->text(), QString("Stopped."));
    QVERIFY(!Find<QPushButton>(d, "apply")->isEnabled());
    Find<QPushButton>(d, "cancel")->click();
    QVERIFY(!d.isVisible());
    QCOMPARE(d.result(), int(QDialog::Rejected));
  }
};

int main(int argc, char** argv) {
  // Settings go to a private folder; widgets to Qt's offscreen platform.
  QTemporaryDir config;
  qputenv("XDG_CONFIG_HOME", config.path().toUtf8());
  if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
  QApplication app(argc, argv);
  DialogTest test;
  return QTest::qExec(&test, argc, argv);
}

#include "dialog_test.moc"
