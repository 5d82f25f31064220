// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/IoOptionsPage.h"

#include "blocks/InstanceVariables.h"
#include "document/PermissionNote.h"
#include "document/ProjectDocument.h"
#include "pages/InstanceVariableText.h"
#include "project/UnitSettings.h"
#include "shell/PageTitle.h"
#include "shell/UnitCaption.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QScrollArea>
#include <QVBoxLayout>

#include <algorithm>

namespace rs::ui {

namespace {

using project::SignalShape;
using project::SignalType;
using project::TerminalKind;
using project::TerminalOption;

enum Column { SignalColumn, TypeColumn, ShapeColumn, FirstOptionColumn };
constexpr int kOptionColumns = 3;
constexpr int kInstanceUsesColumn = FirstOptionColumn + kOptionColumns;

QString groupTitle(TerminalKind kind) {
    switch (kind) {
    case TerminalKind::Input:
        return IoOptionsPage::tr("Failsafe inputs");
    case TerminalKind::Configurable:
        return IoOptionsPage::tr("Failsafe inputs / non-failsafe outputs");
    case TerminalKind::Analogue:
        return IoOptionsPage::tr("Analogue inputs");
    case TerminalKind::SafetyOutput:
        return IoOptionsPage::tr("Safety outputs: test pulses");
    }
    return {};
}

template <typename T> bool has(const std::vector<T>& list, T value) {
    return std::find(list.begin(), list.end(), value) != list.end();
}

// The terminal of an input or output address, if it is one of the type's.
std::optional<project::Terminal> terminalAt(const target::UnitTypeInfo& type,
                                            const lang::Address& address) {
    lang::IoDeclaration io;
    io.io.address = address;
    return project::terminalOf(type, io);
}

} // namespace

QString IoOptionsPage::signalTypeName(SignalType type) {
    switch (type) {
    case SignalType::Undefined:
        return tr("Undefined");
    case SignalType::Input:
        return tr("Input");
    case SignalType::Output:
        return tr("Output");
    case SignalType::LightButton:
        return tr("Light button");
    case SignalType::Voltage:
        return tr("Analogue 0-10 V");
    case SignalType::Current:
        return tr("Analogue 4-20 mA");
    case SignalType::CounterUp:
        return tr("Counter, up");
    case SignalType::CounterUpDown:
        return tr("Counter, up/down");
    }
    return {};
}

QString IoOptionsPage::signalShapeName(SignalShape shape) {
    switch (shape) {
    case SignalShape::None:
        return {};
    case SignalShape::Static:
        return tr("Static");
    case SignalShape::APulse:
        return tr("A_Pulse");
    case SignalShape::BPulse:
        return tr("B_Pulse");
    case SignalShape::CPulse:
        return tr("C_Pulse");
    }
    return {};
}

IoOptionsPage::IoOptionsPage(QWidget* parent)
    : QWidget(parent), m_title(new PageTitle(this)), m_scroll(new QScrollArea(this)) {
    m_scroll->setWidgetResizable(true);
    m_scroll->setFrameShape(QFrame::NoFrame);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addWidget(m_scroll, 1);
}

void IoOptionsPage::showUnit(ProjectDocument* document, int station) {
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    m_station = station;
    m_builtType = -1;
    if (!document)
        return;
    connect(document, &ProjectDocument::changed, this, &IoOptionsPage::refresh);
    connect(document, &ProjectDocument::permissionChanged, this, &IoOptionsPage::refresh);
    refresh();
}

void IoOptionsPage::rebuild() {
    const project::Project& p = m_document->project();
    const target::UnitTypeInfo& type = project::unitTypeOf(p, m_station);
    m_rows.clear();
    delete m_content;
    m_content = new QWidget;
    auto* layout = new QVBoxLayout(m_content);
    layout->setContentsMargins(0, 0, 8, 0);

    const std::vector<project::Terminal> terminals = project::terminalsOf(type, m_station);
    for (TerminalKind kind : {TerminalKind::Input, TerminalKind::Configurable,
                              TerminalKind::Analogue, TerminalKind::SafetyOutput}) {
        if (std::none_of(terminals.begin(), terminals.end(),
                         [&](const auto& t) { return t.kind == kind; }))
            continue;
        auto* group = new QGroupBox(groupTitle(kind), m_content);
        auto* grid = new QGridLayout(group);
        grid->setHorizontalSpacing(14);
        // The same column widths in every group, so the columns line up down the page.
        const QFontMetrics metrics = group->fontMetrics();
        grid->setColumnMinimumWidth(SignalColumn,
                                    metrics.horizontalAdvance(QStringLiteral("IQ00.00")) + 8);
        const bool safety = kind == TerminalKind::SafetyOutput;
        const QStringList headings = safety ? QStringList{tr("Signal"), tr("Options")}
                                            : QStringList{tr("Signal"), tr("Type of signal"),
                                                          tr("Signal shape"), tr("Options")};
        for (int i = 0; i < headings.size(); ++i) {
            auto* heading = new QLabel(QStringLiteral("<b>%1</b>").arg(headings[i]), group);
            grid->addWidget(heading, 0, safety && i == 1 ? FirstOptionColumn : i, 1,
                            i == headings.size() - 1 ? kOptionColumns : 1);
        }
        grid->addWidget(new QLabel(QStringLiteral("<b>%1</b>").arg(tr("Used by block")), group), 0,
                        kInstanceUsesColumn);
        int line = 1;
        for (const auto& terminal : terminals) {
            if (terminal.kind != kind)
                continue;
            Row row;
            row.terminal = terminal;
            const QString label = QString::fromStdString(terminal.label());
            grid->addWidget(new QLabel(label, group), line, SignalColumn);
            auto checkBox = [&](const QString& text, const char* name, int column) {
                auto* box = new QCheckBox(text, group);
                box->setObjectName(QStringLiteral("%1:%2").arg(QLatin1String(name), label));
                grid->addWidget(box, line, column);
                connect(box, &QCheckBox::toggled, this, [this, terminal] {
                    for (const auto& r : m_rows)
                        if (r.terminal == terminal)
                            apply(r);
                });
                return box;
            };
            if (safety) {
                row.noTestPulse = checkBox(tr("No_Test_Pulse"), "noTestPulse", FirstOptionColumn);
            } else {
                row.type = new QComboBox(group);
                row.type->setMinimumContentsLength(16);
                row.type->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
                row.type->setObjectName(QStringLiteral("signalType:%1").arg(label));
                for (SignalType signal : project::signalTypes(type, terminal))
                    row.type->addItem(signalTypeName(signal), static_cast<int>(signal));
                row.shape = new QComboBox(group);
                row.shape->setObjectName(QStringLiteral("signalShape:%1").arg(label));
                row.shape->setMinimumContentsLength(8);
                row.shape->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
                grid->addWidget(row.type, line, TypeColumn);
                grid->addWidget(row.shape, line, ShapeColumn);
                for (QComboBox* combo : {row.type, row.shape})
                    connect(combo, &QComboBox::activated, this, [this, terminal] {
                        for (const auto& r : m_rows)
                            if (r.terminal == terminal)
                                apply(r);
                    });
                row.nonInverted = checkBox(tr("Non_Inv"), "nonInverted", FirstOptionColumn);
                row.noFilter = checkBox(tr("No_Filt"), "noFilter", FirstOptionColumn + 1);
                if (kind == TerminalKind::Configurable)
                    row.crossTalk = checkBox(tr("X_Talk"), "crossTalk", FirstOptionColumn + 2);
            }
            row.instanceUses = new QLabel(group);
            row.instanceUses->setObjectName(QStringLiteral("instanceUses:%1").arg(label));
            grid->addWidget(row.instanceUses, line, kInstanceUsesColumn);
            m_rows.push_back(row);
            ++line;
        }
        grid->setColumnStretch(kInstanceUsesColumn, 1);
        layout->addWidget(group);
    }
    auto* note = new QLabel(tr("The configuration must match the wiring. Q0..Q3 are not listed: "
                               "they can be used in one way only."),
                            m_content);
    note->setWordWrap(true);
    note->setForegroundRole(QPalette::PlaceholderText);
    layout->addWidget(note);
    layout->addStretch();
    m_scroll->setWidget(m_content);
    m_builtType = static_cast<int>(type.type);
}

void IoOptionsPage::refresh() {
    if (!m_document)
        return;
    const project::Project& p = m_document->project();
    if (!project::unitSettings(p, m_station))
        return;
    m_title->setTitle(tr("%1 — I/O Options").arg(unitCaption(p, m_station)));
    const QString note = permissionNote(m_document->permission());
    m_title->setSubtitle(note.isEmpty()
                             ? tr("Choose from the lists what each terminal is wired for; "
                                  "combinations the unit cannot take are not offered.")
                             : note);
    if (m_builtType != static_cast<int>(project::unitTypeOf(p, m_station).type))
        rebuild();
    m_filling = true;
    for (auto& row : m_rows)
        fill(row, project::terminalSetting(p, row.terminal));
    m_filling = false;
    // Password protected without full permission: the choices show, and stay as they are.
    m_content->setEnabled(m_document->permission() == project::Permission::Full);
    showInstanceUses();
}

void IoOptionsPage::showInstanceUses() {
    const project::Project& p = m_document->project();
    const target::UnitTypeInfo& type = project::unitTypeOf(p, m_station);
    const std::vector<blocks::InstanceVariable> uses = blocks::instanceVariables(p, m_station);
    for (auto& row : m_rows) {
        QStringList lines;
        for (const auto& use : uses)
            if (terminalAt(type, use.address) == row.terminal)
                lines << instanceVariableText(use);
        row.instanceUses->setText(lines.join(QLatin1Char('\n')));
    }
}

void IoOptionsPage::fill(Row& row, const project::TerminalSetting& setting) {
    const target::UnitTypeInfo& type = project::unitTypeOf(m_document->project(), m_station);
    if (row.type) {
        row.type->setCurrentIndex(row.type->findData(static_cast<int>(setting.type)));
        row.shape->clear();
        for (SignalShape shape : project::signalShapes(row.terminal, setting.type))
            row.shape->addItem(signalShapeName(shape), static_cast<int>(shape));
        row.shape->setCurrentIndex(row.shape->findData(static_cast<int>(setting.shape)));
        row.shape->setEnabled(row.shape->count() > 0);
    }
    const auto options = project::terminalOptions(type, row.terminal, setting);
    auto set = [&](QCheckBox* box, TerminalOption option, bool on) {
        if (!box)
            return;
        box->setEnabled(has(options, option));
        box->setChecked(on);
    };
    set(row.nonInverted, TerminalOption::NonInverted, setting.nonInverted);
    set(row.noFilter, TerminalOption::NoFilter, setting.noFilter);
    set(row.crossTalk, TerminalOption::CrossTalk, setting.crossTalk);
    set(row.noTestPulse, TerminalOption::NoTestPulse, setting.noTestPulse);
}

project::TerminalSetting IoOptionsPage::settingOf(const Row& row) const {
    project::TerminalSetting setting;
    if (row.type) {
        setting.type = static_cast<SignalType>(row.type->currentData().toInt());
        setting.shape = row.shape->count()
                            ? static_cast<SignalShape>(row.shape->currentData().toInt())
                            : SignalShape::None;
    }
    auto on = [](QCheckBox* box) {
        return box && box->isEnabled() && box->isChecked();
    };
    setting.nonInverted = on(row.nonInverted);
    setting.noFilter = on(row.noFilter);
    setting.crossTalk = on(row.crossTalk);
    setting.noTestPulse = on(row.noTestPulse);
    return setting;
}

void IoOptionsPage::apply(const Row& row) {
    if (m_filling || !m_document)
        return;
    const project::TerminalSetting setting = settingOf(row);
    const project::Terminal terminal = row.terminal;
    const bool changed = m_document->edit(
        tr("Set I/O Options of %1").arg(QString::fromStdString(terminal.label())),
        [&](project::Project& p) { project::setTerminalSetting(p, terminal, setting); });
    if (!changed) // the choice was made legal on the way: show what the project holds
        refresh();
}

} // namespace rs::ui
