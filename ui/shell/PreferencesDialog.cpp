// SPDX-License-Identifier: GPL-3.0-or-later
#include "shell/PreferencesDialog.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPainter>
#include <QPushButton>
#include <QSpinBox>
#include <QToolButton>
#include <QVBoxLayout>

namespace rs::ui {

namespace {

QIcon swatch(const QColor& color) {
    QPixmap pixmap(32, 16);
    pixmap.fill(color);
    QPainter painter(&pixmap);
    painter.setPen(QColor(0x57606a));
    painter.drawRect(pixmap.rect().adjusted(0, 0, -1, -1));
    return QIcon(pixmap);
}

} // namespace

PreferencesDialog::PreferencesDialog(const Preferences& preferences, QWidget* parent)
    : QDialog(parent), m_preferences(preferences), m_updateInterval(new QComboBox(this)),
      m_startExpanded(new QCheckBox(tr("Start with ladder diagrams &expanded"), this)),
      m_warnUnconfiguredIo(new QCheckBox(tr("&Unconfigured I/O warnings at compile time"), this)),
      m_language(new QComboBox(this)), m_theme(new QComboBox(this)), m_autosave(new QSpinBox(this)),
      m_modbusHost(new QLineEdit(this)), m_modbusPort(new QSpinBox(this)) {
    setObjectName(QStringLiteral("preferencesDialog"));
    setWindowTitle(tr("Preferences"));

    auto* colors = new QGroupBox(tr("Ladder colours"), this);
    auto* colorForm = new QFormLayout(colors);
    const std::vector<std::pair<QColor Preferences::*, QString>> fields{
        {&Preferences::ladderBackground, tr("Ladder background:")},
        {&Preferences::ladderFocusedBackground, tr("Focused ladder background:")},
        {&Preferences::ladderComponentBody, tr("Ladder component body:")},
        {&Preferences::ladderLines, tr("Ladder lines:")},
        {&Preferences::ladderLinesOff, tr("Ladder lines off:")},
        {&Preferences::ladderLinesOn, tr("Ladder lines on:")},
    };
    m_colors.reserve(fields.size());
    for (const auto& [member, fieldLabel] : fields) {
        const QString label = fieldLabel; // clang 14 cannot capture a structured binding
        auto* button = new QToolButton(colors);
        button->setIconSize(QSize(32, 16));
        button->setAutoRaise(false);
        m_colors.push_back({member, button});
        const std::size_t index = m_colors.size() - 1;
        connect(button, &QToolButton::clicked, this, [this, index, label] {
            ColorField& field = m_colors[index];
            const QColor shown = m_preferences.*field.member;
            const QColor chosen = QColorDialog::getColor(
                shown.isValid() ? shown : palette().color(QPalette::Base), this, label);
            if (chosen.isValid())
                setColor(field, chosen);
        });
        colorForm->addRow(label, button);
    }
    auto* defaults = new QPushButton(tr("Theme &Colours"), colors);
    defaults->setToolTip(tr("Draw the ladder in the theme's colours again"));
    colorForm->addRow(QString(), defaults);
    connect(defaults, &QPushButton::clicked, this, [this] {
        const Preferences d = Preferences::defaults();
        for (ColorField& field : m_colors)
            setColor(field, d.*field.member);
    });

    for (int ms : {50, 100, 200, 300, 500, 1000})
        m_updateInterval->addItem(tr("%1 ms").arg(ms), ms);
    m_updateInterval->setToolTip(
        tr("Update interval in online mode. A shorter interval makes the computer slower."));
    m_language->addItem(tr("System language"), QString());
    m_language->addItem(QStringLiteral("English"), QStringLiteral("en"));
    m_language->addItem(QStringLiteral("Svenska"), QStringLiteral("sv"));
    m_language->addItem(QStringLiteral("Deutsch"), QStringLiteral("de"));
    m_theme->addItem(tr("Follow the system"), static_cast<int>(Preferences::Theme::System));
    m_theme->addItem(tr("Light"), static_cast<int>(Preferences::Theme::Light));
    m_theme->addItem(tr("Dark"), static_cast<int>(Preferences::Theme::Dark));
    m_autosave->setRange(Preferences::kMinAutosaveMinutes, Preferences::kMaxAutosaveMinutes);
    m_autosave->setSuffix(tr(" min"));
    m_autosave->setObjectName(QStringLiteral("autosaveSpin"));
    const QString autosaveRange = tr("From %1 to %2 minutes. A crash loses at most this much work.")
                                      .arg(Preferences::kMinAutosaveMinutes)
                                      .arg(Preferences::kMaxAutosaveMinutes);
    auto* autosaveNote = new QLabel(autosaveRange, this);
    autosaveNote->setObjectName(QStringLiteral("autosaveNote"));
    autosaveNote->setForegroundRole(QPalette::PlaceholderText);
    m_language->setObjectName(QStringLiteral("languageCombo"));
    m_theme->setObjectName(QStringLiteral("themeCombo"));
    m_warnUnconfiguredIo->setObjectName(QStringLiteral("warnUnconfiguredIoCheck"));
    auto* languageNote = new QLabel(tr("A new language shows when Rungsmith starts again."), this);
    languageNote->setForegroundRole(QPalette::PlaceholderText);

    auto* general = new QGroupBox(tr("General"), this);
    auto* form = new QFormLayout(general);
    form->addRow(tr("Screen update &interval:"), m_updateInterval);
    form->addRow(QString(), m_startExpanded);
    form->addRow(QString(), m_warnUnconfiguredIo);
    form->addRow(tr("&Language:"), m_language);
    form->addRow(QString(), languageNote);
    form->addRow(tr("&Theme:"), m_theme);
    form->addRow(tr("&Autosave every:"), m_autosave);
    form->addRow(QString(), autosaveNote);

    auto* modbus = new QGroupBox(tr("Simulated gateway"), this);
    auto* modbusForm = new QFormLayout(modbus);
    m_modbusHost->setObjectName(QStringLiteral("modbusHostEdit"));
    m_modbusPort->setObjectName(QStringLiteral("modbusPortSpin"));
    m_modbusPort->setRange(1, 65535);
    modbusForm->addRow(tr("Modbus TCP &address:"), m_modbusHost);
    modbusForm->addRow(tr("Modbus TCP &port:"), m_modbusPort);
    auto* modbusNote = new QLabel(tr("Where Serve Modbus TCP listens while simulating. 127.0.0.1 "
                                     "lets only this computer connect; 0.0.0.0 the network."),
                                  this);
    modbusNote->setWordWrap(true);
    modbusNote->setForegroundRole(QPalette::PlaceholderText);
    modbusForm->addRow(QString(), modbusNote);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* columns = new QHBoxLayout;
    auto* left = new QVBoxLayout;
    left->addWidget(general);
    left->addWidget(modbus);
    left->addStretch();
    columns->addLayout(left, 1);
    columns->addWidget(colors);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(columns);
    layout->addWidget(buttons);
    show(preferences);
}

void PreferencesDialog::setColor(ColorField& field, const QColor& color) {
    m_preferences.*field.member = color;
    if (color.isValid()) {
        field.button->setIcon(swatch(color));
        field.button->setText({});
        field.button->setToolButtonStyle(Qt::ToolButtonIconOnly);
        field.button->setToolTip(color.name());
    } else {
        field.button->setIcon({});
        field.button->setText(tr("Theme"));
        field.button->setToolButtonStyle(Qt::ToolButtonTextOnly);
        field.button->setToolTip(tr("As the theme draws it; click to choose a colour"));
    }
}

void PreferencesDialog::show(const Preferences& preferences) {
    for (ColorField& field : m_colors)
        setColor(field, preferences.*field.member);
    const int interval = m_updateInterval->findData(preferences.screenUpdateMs);
    m_updateInterval->setCurrentIndex(interval >= 0 ? interval : 1);
    m_startExpanded->setChecked(preferences.startExpanded);
    m_warnUnconfiguredIo->setChecked(preferences.warnUnconfiguredIo);
    m_language->setCurrentIndex(std::max(0, m_language->findData(preferences.language)));
    m_theme->setCurrentIndex(std::max(0, m_theme->findData(static_cast<int>(preferences.theme))));
    m_autosave->setValue(preferences.autosaveMinutes);
    m_modbusHost->setText(preferences.modbusHost);
    m_modbusPort->setValue(preferences.modbusPort);
}

Preferences PreferencesDialog::preferences() const {
    Preferences p = m_preferences;
    p.screenUpdateMs = m_updateInterval->currentData().toInt();
    p.startExpanded = m_startExpanded->isChecked();
    p.warnUnconfiguredIo = m_warnUnconfiguredIo->isChecked();
    p.language = m_language->currentData().toString();
    p.theme = static_cast<Preferences::Theme>(m_theme->currentData().toInt());
    p.autosaveMinutes = m_autosave->value();
    p.modbusHost = m_modbusHost->text().trimmed().isEmpty() ? Preferences::defaults().modbusHost
                                                            : m_modbusHost->text().trimmed();
    p.modbusPort = m_modbusPort->value();
    return p;
}

} // namespace rs::ui
