// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/ProjectPage.h"

#include "document/ProjectDocument.h"
#include "project/ProjectProperties.h"
#include "project/UnitSettings.h"
#include "shell/PageTitle.h"
#include "shell/StatusColors.h"
#include "shell/UnitCaption.h"

#include <QCheckBox>
#include <QDir>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QVBoxLayout>

namespace rs::ui {

namespace {

constexpr int kDescriptionPauseMs = 600;

} // namespace

ProjectPage::ProjectPage(QWidget* parent)
    : QWidget(parent), m_title(new PageTitle(this)), m_name(new QLineEdit(this)),
      m_nameProblem(new QLabel(this)), m_description(new QPlainTextEdit(this)),
      m_includeSource(new QCheckBox(tr("&Include source code in compiled file"), this)),
      m_file(new QLabel(this)), m_units(new QLabel(this)) {
    m_name->setObjectName(QStringLiteral("projectNameEdit"));
    m_description->setObjectName(QStringLiteral("projectDescriptionEdit"));
    m_description->setTabChangesFocus(true);
    m_description->setMaximumHeight(140);
    m_includeSource->setObjectName(QStringLiteral("includeSourceCheck"));
    // A path breaks at its slashes: shown whole on one line, it stays readable.
    m_file->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_units->setObjectName(QStringLiteral("projectUnitsLabel"));
    markAsError(m_nameProblem);
    m_nameProblem->hide();

    auto* form = new QFormLayout;
    form->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    form->addRow(tr("Project &name:"), m_name);
    form->addRow(QString(), m_nameProblem);
    form->addRow(tr("Project &description:"), m_description);
    form->addRow(QString(), m_includeSource);
    form->addRow(tr("File:"), m_file);
    form->addRow(tr("Units:"), m_units);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(m_title);
    layout->addLayout(form);
    layout->addStretch();

    m_descriptionTimer.setSingleShot(true);
    m_descriptionTimer.setInterval(kDescriptionPauseMs);
    connect(&m_descriptionTimer, &QTimer::timeout, this, &ProjectPage::applyDescription);
    connect(m_description, &QPlainTextEdit::textChanged, this, [this] {
        if (!m_refreshing)
            m_descriptionTimer.start();
    });
    connect(m_name, &QLineEdit::editingFinished, this, &ProjectPage::applyName);
    connect(m_name, &QLineEdit::textEdited, this, [this](const QString& text) {
        const auto problem = project::checkProjectName(text.toStdString());
        m_nameProblem->setText(problem ? QString::fromStdString(*problem) : QString());
        m_nameProblem->setVisible(problem.has_value());
    });
    connect(m_includeSource, &QCheckBox::toggled, this, [this](bool on) {
        if (m_refreshing || !m_document)
            return;
        m_document->edit(on ? tr("Include Source Code") : tr("Leave Out Source Code"),
                         [on](project::Project& p) { p.includeSource = on; });
    });
}

void ProjectPage::showProject(ProjectDocument* document) {
    if (m_document) {
        applyDescription();
        disconnect(m_document, nullptr, this, nullptr);
    }
    m_document = document;
    if (!document)
        return;
    connect(document, &ProjectDocument::changed, this, &ProjectPage::refresh);
    connect(document, &ProjectDocument::pathChanged, this, &ProjectPage::refresh);
    refresh();
}

void ProjectPage::refresh() {
    if (!m_document)
        return;
    m_refreshing = true;
    const project::Project& p = m_document->project();
    m_title->setTitle(tr("Project %1").arg(QString::fromStdString(p.name())));
    if (!m_name->hasFocus())
        m_name->setText(QString::fromStdString(p.name()));
    const QString description = QString::fromStdString(p.description);
    if (m_description->toPlainText() != description && !m_descriptionTimer.isActive())
        m_description->setPlainText(description);
    m_includeSource->setChecked(p.includeSource);
    m_file->setText(m_document->path().isEmpty() ? tr("Not saved yet")
                                                 : QDir::toNativeSeparators(m_document->path()));
    QStringList units;
    for (const auto& unit : project::unitsOf(p))
        units << unitCaption(unit);
    m_units->setText(units.isEmpty() ? tr("None yet. Add one with Project > New Pluto.")
                                     : units.join(QStringLiteral(", ")));
    m_refreshing = false;
}

void ProjectPage::applyName() {
    if (!m_document)
        return;
    const std::string name = m_name->text().toStdString();
    if (project::checkProjectName(name) || name == m_document->project().name())
        return;
    m_document->edit(tr("Rename Project"),
                     [&](project::Project& p) { project::setProjectName(p, name); });
}

void ProjectPage::applyDescription() {
    m_descriptionTimer.stop();
    if (!m_document)
        return;
    const std::string description = m_description->toPlainText().toStdString();
    m_document->edit(tr("Change Project Description"),
                     [&](project::Project& p) { p.description = description; });
}

} // namespace rs::ui
