// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/UnitSettingsForm.h"

#include "project/UnitSettings.h"
#include "shell/StatusColors.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QRadioButton>
#include <QRegularExpressionValidator>

namespace rs::ui {

namespace {

QString display(const target::UnitTypeInfo& type) {
    return QString::fromUtf8(type.display.data(), static_cast<qsizetype>(type.display.size()));
}

enum IdfixKind { IdfixNumber = 0, NoIdfix = 1, IdfixProg = 2 };

} // namespace

UnitSettingsForm::UnitSettingsForm(QWidget* parent)
    : QWidget(parent), m_station(new QComboBox(this)), m_type(new QComboBox(this)),
      m_set2(new QRadioButton(tr("Instruction set &2"), this)),
      m_set3(new QRadioButton(tr("Instruction set &3"), this)), m_sets(new QButtonGroup(this)),
      m_setNote(new QLabel(this)), m_idfixKind(new QComboBox(this)), m_idfix(new QLineEdit(this)),
      m_description(new QLineEdit(this)), m_problem(new QLabel(this)) {
    m_station->setObjectName(QStringLiteral("stationCombo"));
    m_type->setObjectName(QStringLiteral("typeCombo"));
    m_set2->setObjectName(QStringLiteral("instructionSet2"));
    m_set3->setObjectName(QStringLiteral("instructionSet3"));
    m_idfixKind->setObjectName(QStringLiteral("idfixKindCombo"));
    m_idfix->setObjectName(QStringLiteral("idfixEdit"));
    m_description->setObjectName(QStringLiteral("unitDescriptionEdit"));
    m_problem->setObjectName(QStringLiteral("unitProblemLabel"));

    for (const auto& type : target::unitTypes())
        m_type->addItem(display(type), static_cast<int>(type.type));
    m_sets->addButton(m_set2, 2);
    m_sets->addButton(m_set3, 3);
    m_setNote->setWordWrap(true);
    m_setNote->setText(
        tr("Instruction set 3 needs Pluto OS 3.0 or later. It adds the off-delay timer, "
           "multiplication and division with constants, double registers (32 bits), \"not "
           "positive edge\" and \"not negative edge\", register bits and a larger address range."));
    m_setNote->setForegroundRole(QPalette::PlaceholderText);
    m_setNote->setMinimumWidth(420);
    m_idfixKind->addItem(tr("IDFIX number"), IdfixNumber);
    m_idfixKind->addItem(tr("No IDFIX"), NoIdfix);
    m_idfixKind->addItem(tr("IDFIX-PROG"), IdfixProg);
    m_idfixKind->setItemData(IdfixProg,
                             tr("A programmable identifier circuit: the number given here is the "
                                "one written to it (Write IDFIX, on the unit)."),
                             Qt::ToolTipRole);
    m_idfix->setValidator(new QRegularExpressionValidator(
        QRegularExpression(QStringLiteral("[0-9A-Fa-f]{0,12}")), m_idfix));
    m_idfix->setPlaceholderText(tr("12 hexadecimal digits, e.g. 000034AD4AE1"));
    m_idfix->setMaxLength(12);
    m_idfix->setMinimumWidth(
        m_idfix->fontMetrics().horizontalAdvance(QStringLiteral("0000AAAA0000")) + 24);
    m_description->setPlaceholderText(tr("For your own notes; not downloaded to the unit"));
    m_description->setMinimumWidth(420);
    markAsError(m_problem);
    m_problem->setWordWrap(true);
    m_problem->hide();

    auto* sets = new QHBoxLayout;
    sets->addWidget(m_set2);
    sets->addWidget(m_set3);
    sets->addStretch();
    auto* idfix = new QHBoxLayout;
    idfix->addWidget(m_idfixKind);
    idfix->addWidget(m_idfix, 1);
    idfix->addStretch(1);

    auto* form = new QFormLayout(this);
    form->setContentsMargins(0, 0, 0, 0);
    form->setFieldGrowthPolicy(QFormLayout::FieldsStayAtSizeHint);
    form->addRow(tr("&Station number:"), m_station);
    form->addRow(tr("Pluto &type:"), m_type);
    form->addRow(tr("Instruction set:"), sets);
    form->addRow(QString(), m_setNote);
    auto* idfixLabel = new QLabel(tr("&IDFIX:"), this);
    idfixLabel->setBuddy(m_idfix);
    form->addRow(idfixLabel, idfix);
    form->addRow(tr("&Description:"), m_description);
    form->addRow(QString(), m_problem);

    auto changed = [this] {
        if (!m_filling)
            emit edited();
    };
    connect(m_station, &QComboBox::activated, this, changed);
    connect(m_type, &QComboBox::currentIndexChanged, this, [this, changed] {
        updateInstructionSets();
        changed();
    });
    connect(m_sets, &QButtonGroup::idClicked, this, changed);
    connect(m_idfixKind, &QComboBox::currentIndexChanged, this, [this, changed] {
        updateIdfix();
        changed();
    });
    connect(m_idfix, &QLineEdit::textEdited, this, &UnitSettingsForm::updateIdfix);
    connect(m_idfix, &QLineEdit::editingFinished, this, changed);
    connect(m_description, &QLineEdit::editingFinished, this, changed);
}

void UnitSettingsForm::setSettings(const project::UnitSettings& settings,
                                   const std::vector<int>& freeStations, bool stationFixed) {
    m_filling = true;
    m_station->clear();
    std::vector<int> stations = freeStations;
    if (std::find(stations.begin(), stations.end(), settings.station) == stations.end())
        stations.push_back(settings.station);
    std::sort(stations.begin(), stations.end());
    for (int station : stations)
        m_station->addItem(QString::number(station), station);
    m_station->setCurrentIndex(m_station->findData(settings.station));
    m_station->setEnabled(!stationFixed);
    m_type->setCurrentIndex(m_type->findData(static_cast<int>(settings.type)));
    (settings.instructionSet >= 3 ? m_set3 : m_set2)->setChecked(true);
    const bool noIdfix = settings.idfix == project::kNoIdfix && !settings.idfixProg;
    m_idfixKind->setCurrentIndex(settings.idfixProg ? IdfixProg : noIdfix ? NoIdfix : IdfixNumber);
    m_idfix->setText(noIdfix ? QString() : QString::fromStdString(settings.idfix));
    if (m_description->text() != QString::fromStdString(settings.description))
        m_description->setText(QString::fromStdString(settings.description));
    updateInstructionSets();
    updateIdfix();
    m_filling = false;
}

project::UnitSettings UnitSettingsForm::settings() const {
    project::UnitSettings settings;
    settings.station = m_station->currentData().toInt();
    settings.type = static_cast<target::UnitType>(m_type->currentData().toInt());
    settings.instructionSet = m_set3->isChecked() && m_set3->isEnabled() ? 3 : 2;
    settings.idfix = m_idfixKind->currentData().toInt() == NoIdfix
                         ? std::string(project::kNoIdfix)
                         : m_idfix->text().toUpper().toStdString();
    settings.idfixProg = m_idfixKind->currentData().toInt() == IdfixProg;
    settings.description = m_description->text().toStdString();
    return settings;
}

QString UnitSettingsForm::problem() const {
    if (m_idfixKind->currentData().toInt() != NoIdfix && m_idfix->text().size() != 12)
        return tr("The IDFIX number has %n of its 12 hexadecimal digits. Choose \"No IDFIX\" if "
                  "the unit has no identifier circuit.",
                  nullptr, static_cast<int>(m_idfix->text().size()));
    return {};
}

void UnitSettingsForm::updateInstructionSets() {
    const auto type = static_cast<target::UnitType>(m_type->currentData().toInt());
    const bool set3 = project::supportsInstructionSet3(type);
    m_set3->setEnabled(set3);
    if (!set3)
        m_set2->setChecked(true);
    m_set3->setToolTip(
        set3 ? QString()
             : tr("The %1 runs instruction set 2 only.").arg(display(target::unitTypeInfo(type))));
}

void UnitSettingsForm::updateIdfix() {
    m_idfix->setEnabled(m_idfixKind->currentData().toInt() != NoIdfix);
    const QString text = problem();
    m_problem->setText(text);
    m_problem->setVisible(!text.isEmpty());
}

} // namespace rs::ui
