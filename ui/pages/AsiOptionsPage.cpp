// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/AsiOptionsPage.h"

#include "document/PermissionNote.h"
#include "document/ProjectDocument.h"
#include "pages/AsiProfileDialog.h"
#include "project/UnitAsiOptions.h"
#include "project/UnitSettings.h"
#include "shell/PageTitle.h"
#include "shell/UnitCaption.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QStandardItemModel>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace rs::ui {

namespace {

using project::AsiMode;
using project::AsiOptimisation;
using project::AsiSlave;
using project::AsiSlaveAddress;
using project::AsiSlaveType;
using project::ChannelMonitoring;

enum Column {
    SlaveColumn,
    TypeColumn,
    ModelColumn,
    ParameterColumn,
    ProfileColumn,
    MonitoringColumn,
    TimeLimitColumn
};

constexpr AsiMode kModes[] = {AsiMode::Master, AsiMode::MonitorOnly, AsiMode::MonitorSlave,
                              AsiMode::MonitorSlaveExtra, AsiMode::Unused};
constexpr ChannelMonitoring kMonitorings[] = {
    ChannelMonitoring::None, ChannelMonitoring::Monitoring, ChannelMonitoring::MonitoringDebounce,
    ChannelMonitoring::Simultaneous, ChannelMonitoring::SimultaneousDebounce};

bool ownSlaveAddress(AsiMode mode) {
    return mode == AsiMode::MonitorSlave || mode == AsiMode::MonitorSlaveExtra;
}

bool usesBlockSlot(AsiSlaveType type) {
    return type == AsiSlaveType::SafeOutput || type == AsiSlaveType::PlutoAsSafeInput;
}

int blockSlaves(const project::AsiOptions& options) {
    return static_cast<int>(
        std::count_if(options.slaves.begin(), options.slaves.end(),
                      [](const auto& s) { return usesBlockSlot(s.second.type); }));
}

} // namespace

QString AsiOptionsPage::modeName(AsiMode mode) {
    switch (mode) {
    case AsiMode::Master:
        return tr("Bus Master");
    case AsiMode::MonitorOnly:
        return tr("Monitor only");
    case AsiMode::MonitorSlave:
        return tr("Monitor / Slave");
    case AsiMode::MonitorSlaveExtra:
        return tr("Monitor / Slave with 3 extra virtual slaves");
    case AsiMode::Unused:
        return tr("AS-i bus not used");
    }
    return {};
}

QString AsiOptionsPage::slaveTypeName(AsiSlaveType type, bool bAddress) {
    switch (type) {
    case AsiSlaveType::Undefined:
        return tr("Undefined");
    case AsiSlaveType::SafeInput:
        return tr("Safe Input");
    case AsiSlaveType::NonsafeStandard:
        return tr("Nonsafe Std");
    case AsiSlaveType::NonsafeAB:
        return bAddress ? tr("Nonsafe B") : tr("Nonsafe A");
    case AsiSlaveType::CombinedTransaction:
        return bAddress ? tr("Combined Transaction B") : tr("Combined Transaction A");
    case AsiSlaveType::Analogue:
        return tr("Analog");
    case AsiSlaveType::SafeOutput:
        return tr("Safe Output");
    case AsiSlaveType::PlutoAsSafeInput:
        return tr("Pluto as Safe Input");
    }
    return {};
}

QString AsiOptionsPage::monitoringName(ChannelMonitoring monitoring) {
    switch (monitoring) {
    case ChannelMonitoring::None:
        return tr("No channel monitoring");
    case ChannelMonitoring::Monitoring:
        return tr("Channel monitoring");
    case ChannelMonitoring::MonitoringDebounce:
        return tr("Chan mon & debounce filter");
    case ChannelMonitoring::Simultaneous:
        return tr("Simultaneously");
    case ChannelMonitoring::SimultaneousDebounce:
        return tr("Simultaneously & debounce");
    }
    return {};
}

AsiOptionsPage::AsiOptionsPage(QWidget* parent)
    : QWidget(parent), m_title(new PageTitle(this)), m_scroll(new QScrollArea(this)) {
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(m_scroll, 1);
    build();
}

QString AsiOptionsPage::slaveLabel(AsiSlaveAddress address) const {
    return QString::fromStdString(project::slaveLabel(m_station, address));
}

void AsiOptionsPage::build() {
    m_content = new QWidget;
    auto* layout = new QVBoxLayout(m_content);
    layout->setContentsMargins(0, 0, 8, 0);

    auto* bus = new QGroupBox(tr("AS-i general options"), m_content);
    auto* busLayout = new QGridLayout(bus);
    busLayout->setHorizontalSpacing(24);
    auto* modeBox = new QVBoxLayout;
    modeBox->addWidget(
        new QLabel(QStringLiteral("<b>%1</b>").arg(tr("AS-i bus working mode")), bus));
    m_modes = new QButtonGroup(this);
    for (AsiMode mode : kModes) {
        auto* button = new QRadioButton(modeName(mode), bus);
        button->setObjectName(
            QStringLiteral("asiMode:%1").arg(QString::fromUtf8(project::modeWord(mode).data())));
        m_modes->addButton(button, static_cast<int>(mode));
        modeBox->addWidget(button);
    }
    connect(m_modes, &QButtonGroup::idClicked, this, [this](int id) {
        changeBus(tr("Set AS-i bus working mode"),
                  [id](project::AsiOptions& o) { o.mode = static_cast<AsiMode>(id); });
    });
    auto* addressRow = new QHBoxLayout;
    m_slaveAddress = new QSpinBox(bus);
    m_slaveAddress->setObjectName(QStringLiteral("asiSlaveAddress"));
    m_slaveAddress->setRange(1, project::kAsiSlaveCount);
    m_slaveAddress->setKeyboardTracking(false);
    auto* addressLabel = new QLabel(tr("ASi &slave address:"), bus);
    addressLabel->setBuddy(m_slaveAddress);
    addressRow->addWidget(addressLabel);
    addressRow->addWidget(m_slaveAddress);
    addressRow->addStretch();
    modeBox->addLayout(addressRow);
    connect(m_slaveAddress, &QSpinBox::valueChanged, this, [this](int value) {
        changeBus(tr("Set AS-i slave address"),
                  [value](project::AsiOptions& o) { o.slaveAddress = value; });
    });
    modeBox->addStretch();
    busLayout->addLayout(modeBox, 0, 0);

    auto* optimiseBox = new QVBoxLayout;
    optimiseBox->addWidget(new QLabel(QStringLiteral("<b>%1</b>").arg(tr("Optimize for")), bus));
    m_optimisation = new QButtonGroup(this);
    const std::pair<AsiOptimisation, QString> optimisations[] = {
        {AsiOptimisation::ShortStopTime, tr("Short stop time (worst case, when error)")},
        {AsiOptimisation::DisturbanceImmunity, tr("Disturbance immunity")}};
    for (const auto& [optimisation, text] : optimisations) {
        auto* button = new QRadioButton(text, bus);
        button->setObjectName(
            QStringLiteral("asiOptimize:%1")
                .arg(QString::fromUtf8(project::optimisationWord(optimisation).data())));
        m_optimisation->addButton(button, static_cast<int>(optimisation));
        optimiseBox->addWidget(button);
    }
    auto* immunityNote = new QLabel(tr("Disturbance immunity is not recommended when fewer than "
                                       "20 slaves are used: the worst case stop time grows by "
                                       "10 ms."),
                                    bus);
    immunityNote->setWordWrap(true);
    immunityNote->setForegroundRole(QPalette::PlaceholderText);
    optimiseBox->addWidget(immunityNote);
    connect(m_optimisation, &QButtonGroup::idClicked, this, [this](int id) {
        changeBus(tr("Set AS-i optimisation"), [id](project::AsiOptions& o) {
            o.optimisation = static_cast<AsiOptimisation>(id);
        });
    });
    optimiseBox->addStretch();
    busLayout->addLayout(optimiseBox, 0, 1);
    busLayout->setColumnStretch(1, 1);
    layout->addWidget(bus);

    auto* slaves = new QGroupBox(tr("AS-i slaves"), m_content);
    auto* grid = new QGridLayout(slaves);
    grid->setHorizontalSpacing(8);
    grid->setVerticalSpacing(4);
    const QString headings[] = {tr("Slave No"),  tr("Type of Slave"), tr("Model"),
                                tr("Param"),     tr("Profile/ID1"),   tr("Channel Monitoring"),
                                tr("Time limit")};
    for (int column = 0; column < 7; ++column)
        grid->addWidget(new QLabel(QStringLiteral("<b>%1</b>").arg(headings[column]), slaves), 0,
                        column);
    int line = 1;
    for (int number = 1; number <= project::kAsiSlaveCount; ++number) {
        for (bool b : {false, true}) {
            Row row;
            row.address = {number, b};
            const AsiSlaveAddress address = row.address;
            const QString key = QString::number(number) + (b ? QStringLiteral("B") : QString());
            row.label = new QLabel(slaves);
            row.label->setObjectName(QStringLiteral("asiSlave:%1").arg(key));
            grid->addWidget(row.label, line, SlaveColumn);
            row.type = new QComboBox(slaves);
            row.type->setObjectName(QStringLiteral("asiType:%1").arg(key));
            row.type->setSizeAdjustPolicy(QComboBox::AdjustToContents);
            // The whole list a B address can ever take; fill() disables what is not legal now.
            for (AsiSlaveType type : project::slaveTypesAt(
                     {number, b}, b ? AsiSlaveType::NonsafeAB : AsiSlaveType::Undefined))
                row.type->addItem(slaveTypeName(type, b), static_cast<int>(type));
            row.label->setBuddy(row.type);
            connect(row.type, &QComboBox::activated, this, [this, address](int index) {
                const QComboBox* combo = nullptr;
                for (const auto& r : m_rows)
                    if (r.address == address)
                        combo = r.type;
                const auto type = static_cast<AsiSlaveType>(combo->itemData(index).toInt());
                changeSlave(address, [type](AsiSlave& slave) {
                    if (slave.type != type)
                        slave = project::defaultSlave(type);
                });
            });
            grid->addWidget(row.type, line, TypeColumn);

            row.model = new QComboBox(slaves);
            row.model->setObjectName(QStringLiteral("asiModel:%1").arg(key));
            for (std::string_view model : project::asiSafeInputModels())
                row.model->addItem(QString::fromUtf8(model.data(), static_cast<int>(model.size())));
            connect(row.model, &QComboBox::activated, this, [this, address](int index) {
                const std::string model(
                    project::asiSafeInputModels()[static_cast<std::size_t>(index)]);
                changeSlave(address, [model](AsiSlave& slave) { slave.model = model; });
            });
            grid->addWidget(row.model, line, ModelColumn);

            row.parameter = new QComboBox(slaves);
            row.parameter->setObjectName(QStringLiteral("asiParam:%1").arg(key));
            for (int digit = 0; digit <= 0xF; ++digit)
                row.parameter->addItem(QString::number(digit, 16).toUpper());
            connect(row.parameter, &QComboBox::activated, this, [this, address](int value) {
                changeSlave(address, [value](AsiSlave& slave) { slave.parameter = value; });
            });
            grid->addWidget(row.parameter, line, ParameterColumn);

            row.profile = new QPushButton(slaves);
            row.profile->setObjectName(QStringLiteral("asiProfile:%1").arg(key));
            row.profile->setMinimumWidth(
                row.profile->fontMetrics().horizontalAdvance(QStringLiteral("S-0.B.F ID1=F")) + 24);
            connect(row.profile, &QPushButton::clicked, this,
                    [this, address] { editProfile(address); });
            grid->addWidget(row.profile, line, ProfileColumn);

            row.monitoring = new QComboBox(slaves);
            row.monitoring->setObjectName(QStringLiteral("asiMonitoring:%1").arg(key));
            for (ChannelMonitoring monitoring : kMonitorings)
                row.monitoring->addItem(monitoringName(monitoring), static_cast<int>(monitoring));
            connect(row.monitoring, &QComboBox::activated, this, [this, address](int index) {
                const auto monitoring = kMonitorings[index];
                changeSlave(address,
                            [monitoring](AsiSlave& slave) { slave.monitoring = monitoring; });
            });
            grid->addWidget(row.monitoring, line, MonitoringColumn);

            row.timeLimit = new QDoubleSpinBox(slaves);
            row.timeLimit->setObjectName(QStringLiteral("asiTimeLimit:%1").arg(key));
            row.timeLimit->setDecimals(2);
            row.timeLimit->setRange(project::kMinAsiTimeLimitMs / 1000.0,
                                    project::kMaxAsiTimeLimitMs / 1000.0);
            row.timeLimit->setSingleStep(0.1);
            row.timeLimit->setSuffix(tr(" s"));
            row.timeLimit->setKeyboardTracking(false);
            connect(row.timeLimit, &QDoubleSpinBox::valueChanged, this,
                    [this, address](double seconds) {
                        const int ms = static_cast<int>(std::lround(seconds * 1000));
                        changeSlave(address, [ms](AsiSlave& slave) { slave.timeLimitMs = ms; });
                    });
            grid->addWidget(row.timeLimit, line, TimeLimitColumn);
            m_rows.push_back(row);
            ++line;
        }
    }
    grid->setColumnStretch(TimeLimitColumn + 1, 1);
    layout->addWidget(slaves);

    m_blockSlaves = new QLabel(m_content);
    m_blockSlaves->setWordWrap(true);
    m_blockSlaves->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(m_blockSlaves);
    auto* online = new QLabel(
        tr("Reading the slaves from the bus, teaching safety codes, the code tables and changing "
           "a slave's address need a Pluto on a real AS-i bus, and are not in Rungsmith. A slave "
           "the code uses but this table does not define is a warning when compiling; the "
           "simulator gives each safe input slave two channels that follow its channel "
           "monitoring."),
        m_content);
    online->setWordWrap(true);
    online->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(online);
    layout->addStretch();
    m_scroll->setWidget(m_content);
}

void AsiOptionsPage::showUnit(ProjectDocument* document, int station) {
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    m_station = station;
    if (!document)
        return;
    connect(document, &ProjectDocument::changed, this, &AsiOptionsPage::refresh);
    connect(document, &ProjectDocument::permissionChanged, this, &AsiOptionsPage::refresh);
    refresh();
}

void AsiOptionsPage::refresh() {
    if (!m_document)
        return;
    const project::Project& p = m_document->project();
    if (!project::unitSettings(p, m_station))
        return;
    m_title->setTitle(tr("%1 — AS-i Options").arg(unitCaption(p, m_station)));
    const QString note = permissionNote(m_document->permission());
    m_title->setSubtitle(note.isEmpty() ? tr("How the unit works on its AS-i bus, and what each "
                                             "slave address holds (manual Part 1, 7.1).")
                                        : note);
    const project::AsiOptions options = project::asiOptionsOf(p, m_station);
    m_filling = true;
    m_modes->button(static_cast<int>(options.mode))->setChecked(true);
    m_slaveAddress->setValue(options.slaveAddress);
    m_slaveAddress->setEnabled(ownSlaveAddress(options.mode));
    m_optimisation->button(static_cast<int>(options.optimisation))->setChecked(true);
    for (auto& row : m_rows)
        fill(row, options);
    m_filling = false;
    m_blockSlaves->setText(tr("%1 of %2 slaves are Safe Output or Pluto as Safe Input, the most "
                              "a Pluto takes.")
                               .arg(blockSlaves(options))
                               .arg(project::kMaxAsiBlockSlaves));
    m_content->setEnabled(m_document->permission() == project::Permission::Full);
}

void AsiOptionsPage::fill(Row& row, const project::AsiOptions& options) {
    const auto found = options.slaves.find(row.address);
    const AsiSlave slave = found == options.slaves.end() ? AsiSlave{} : found->second;
    row.label->setText(slaveLabel(row.address));

    // What the type list offers: a B address only beside an A/B slave or none,
    // and no more block slaves once the unit has as many as it takes.
    AsiSlaveType aType = AsiSlaveType::Undefined;
    if (auto a = options.slaves.find({row.address.number, false}); a != options.slaves.end())
        aType = a->second.type;
    const auto offered = project::slaveTypesAt(row.address, aType);
    const bool full = blockSlaves(options) >= project::kMaxAsiBlockSlaves;
    auto* model = qobject_cast<QStandardItemModel*>(row.type->model());
    for (int i = 0; i < row.type->count(); ++i) {
        const auto type = static_cast<AsiSlaveType>(row.type->itemData(i).toInt());
        const bool allowed = std::find(offered.begin(), offered.end(), type) != offered.end() &&
                             (!full || !usesBlockSlot(type) || usesBlockSlot(slave.type));
        model->item(i)->setEnabled(allowed);
    }
    row.type->setCurrentIndex(row.type->findData(static_cast<int>(slave.type)));
    row.type->setEnabled(offered.size() > 1);
    row.type->setToolTip(offered.size() > 1
                             ? QString()
                             : tr("%1 takes the whole address: a B slave only goes beside an A/B "
                                  "slave.")
                                   .arg(slaveLabel({row.address.number, false})));

    const bool defined = slave.type != AsiSlaveType::Undefined;
    const bool safeInput = slave.type == AsiSlaveType::SafeInput;
    row.model->setVisible(safeInput);
    row.model->setCurrentText(QString::fromStdString(slave.model));
    row.parameter->setVisible(defined);
    row.parameter->setCurrentIndex(slave.parameter);
    const bool profile = project::hasProfile(slave.type, slave.model);
    row.profile->setVisible(profile);
    row.profile->setText(QString::fromStdString(project::profileText(slave.profile)));
    const bool channels = project::hasChannels(slave.type);
    row.monitoring->setVisible(channels);
    row.monitoring->setCurrentIndex(static_cast<int>(slave.monitoring));
    const bool ownChannels = safeInput && project::monitorsOwnChannels(slave.model);
    row.monitoring->setEnabled(!ownChannels);
    row.monitoring->setToolTip(
        ownChannels
            ? tr("%1 monitors its channels itself.").arg(QString::fromStdString(slave.model))
            : QString());
    row.timeLimit->setVisible(channels && project::usesTimeLimit(slave.monitoring));
    row.timeLimit->setValue(slave.timeLimitMs / 1000.0);
}

void AsiOptionsPage::changeBus(const QString& text,
                               const std::function<void(project::AsiOptions&)>& change) {
    if (m_filling || !m_document)
        return;
    const int station = m_station;
    if (!m_document->edit(text, [&](project::Project& p) {
            project::AsiOptions options = project::asiOptionsOf(p, station);
            change(options);
            project::setAsiOptions(p, station, options);
        }))
        refresh();
}

void AsiOptionsPage::changeSlave(AsiSlaveAddress address,
                                 const std::function<void(AsiSlave&)>& change) {
    if (m_filling || !m_document)
        return;
    const int station = m_station;
    project::AsiOptions options = project::asiOptionsOf(m_document->project(), station);
    auto found = options.slaves.find(address);
    AsiSlave slave = found == options.slaves.end() ? AsiSlave{} : found->second;
    change(slave);
    // The choices offered are the legal ones; a refusal shows what the project holds.
    if (project::setSlave(options, address, slave) ||
        !m_document->edit(
            tr("Set AS-i slave %1").arg(slaveLabel(address)),
            [&](project::Project& p) { project::setAsiOptions(p, station, options); }))
        refresh();
}

void AsiOptionsPage::editProfile(AsiSlaveAddress address) {
    if (!m_document)
        return;
    const project::AsiOptions options = project::asiOptionsOf(m_document->project(), m_station);
    const auto found = options.slaves.find(address);
    if (found == options.slaves.end())
        return;
    AsiProfileDialog dialog(slaveLabel(address), found->second.profile, this);
    if (dialog.exec() != QDialog::Accepted)
        return;
    const project::AsiProfile profile = dialog.profile();
    changeSlave(address, [profile](AsiSlave& slave) { slave.profile = profile; });
}

} // namespace rs::ui
