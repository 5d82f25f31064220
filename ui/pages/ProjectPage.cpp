// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/ProjectPage.h"

#include "blocks/LibrarySearch.h"
#include "blocks/ProjectInstances.h"
#include "compiler/Signature.h"
#include "document/ProjectDocument.h"
#include "output/SettledCompile.h"
#include "pages/SignatureLabel.h"
#include "project/ProjectProperties.h"
#include "project/UnitSettings.h"
#include "shell/PageTitle.h"
#include "shell/StatusColors.h"
#include "shell/UnitCaption.h"

#include <QCheckBox>
#include <QCoreApplication>
#include <QDir>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

#include <algorithm>
#include <set>

namespace rs::ui {

namespace {

constexpr int kDescriptionPauseMs = 600;

} // namespace

ProjectPage::ProjectPage(QWidget* parent)
    : QWidget(parent), m_title(new PageTitle(this)), m_name(new QLineEdit(this)),
      m_nameProblem(new QLabel(this)), m_description(new QPlainTextEdit(this)),
      m_includeSource(new QCheckBox(tr("&Include source code in compiled file"), this)),
      m_file(new QLabel(this)), m_units(new QLabel(this)), m_signature(new SignatureLabel(this)),
      m_validated(new QLabel(this)), m_sinceValidation(new QLabel(this)),
      m_protection(new QLabel(this)), m_form(new QFormLayout), m_libraries(new QListWidget(this)),
      m_addStandard(new QPushButton(tr("Add &Standard Library"), this)),
      m_addUser(new QPushButton(tr("Add &User Library..."), this)),
      m_remove(new QPushButton(tr("&Remove Library"), this)) {
    m_libraries->setObjectName(QStringLiteral("projectLibrariesList"));
    m_libraries->setMaximumHeight(110);
    m_addStandard->setObjectName(QStringLiteral("addStandardLibraryButton"));
    m_addUser->setObjectName(QStringLiteral("addUserLibraryButton"));
    m_remove->setObjectName(QStringLiteral("removeLibraryButton"));
    // The standard libraries are offered as they are found when the menu opens.
    auto* standardMenu = new QMenu(m_addStandard);
    m_addStandard->setMenu(standardMenu);
    connect(standardMenu, &QMenu::aboutToShow, this, [this, standardMenu] {
        standardMenu->clear();
        if (!m_document)
            return;
        const auto& used = m_document->project().libraries;
        const blocks::LibrarySet found = blocks::loadLibraries(
            blocks::standardLibraryFolders(QCoreApplication::applicationDirPath()), {}, {});
        for (const auto& loaded : found.libraries) {
            const QString name = QString::fromStdString(loaded.library.name);
            QAction* add = standardMenu->addAction(name, this, [this, name] { addLibrary(name); });
            add->setEnabled(std::find(used.begin(), used.end(), loaded.library.name) == used.end());
        }
        if (found.libraries.empty())
            standardMenu->addAction(tr("No standard library is installed"))->setEnabled(false);
    });
    connect(m_addUser, &QPushButton::clicked, this, &ProjectPage::addUserLibrary);
    connect(m_remove, &QPushButton::clicked, this, &ProjectPage::removeLibrary);
    connect(m_libraries, &QListWidget::currentRowChanged, this, [this](int row) {
        m_remove->setEnabled(row >= 0 && m_document &&
                             m_document->permission() == project::Permission::Full);
    });
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

    QFormLayout* form = m_form;
    form->setFieldGrowthPolicy(QFormLayout::ExpandingFieldsGrow);
    form->addRow(tr("Project &name:"), m_name);
    form->addRow(QString(), m_nameProblem);
    form->addRow(tr("Project &description:"), m_description);
    form->addRow(QString(), m_includeSource);
    form->addRow(tr("File:"), m_file);
    form->addRow(tr("Units:"), m_units);
    m_signature->setObjectName(QStringLiteral("projectSignature"));
    form->addRow(tr("Program signature:"), m_signature);
    m_validated->setObjectName(QStringLiteral("validatedLabel"));
    form->addRow(tr("Validated:"), m_validated);
    m_sinceValidation->setObjectName(QStringLiteral("sinceValidationLabel"));
    m_sinceValidation->setTextInteractionFlags(Qt::TextSelectableByMouse);
    form->addRow(tr("Since then:"), m_sinceValidation);
    m_protection->setObjectName(QStringLiteral("protectionLabel"));
    m_protection->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // Two lines of their own: a wrapping label in a form row is given one line's height.
    form->addRow(tr("Protection:"), m_protection);
    auto* libraryButtons = new QHBoxLayout;
    libraryButtons->addWidget(m_addStandard);
    libraryButtons->addWidget(m_addUser);
    libraryButtons->addWidget(m_remove);
    libraryButtons->addStretch();
    auto* libraries = new QVBoxLayout;
    libraries->addWidget(m_libraries);
    libraries->addLayout(libraryButtons);
    auto* librariesLabel = new QLabel(tr("Function &libraries:"), this);
    librariesLabel->setBuddy(m_libraries);
    form->addRow(librariesLabel, libraries);
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
    m_signature->setSource(document, SignatureLabel::kProject);
    if (m_compile)
        disconnect(m_compile, nullptr, this, nullptr);
    m_compile = document ? SettledCompile::of(document) : nullptr;
    if (!document)
        return;
    m_compile->addViewer(m_sinceValidation);
    connect(m_compile, &SettledCompile::outdated, this, &ProjectPage::refreshSinceValidation);
    connect(m_compile, &SettledCompile::computed, this, &ProjectPage::refreshSinceValidation);
    connect(document, &ProjectDocument::changed, this, &ProjectPage::refresh);
    connect(document, &ProjectDocument::pathChanged, this, &ProjectPage::refresh);
    connect(document, &ProjectDocument::permissionChanged, this, &ProjectPage::refresh);
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
    if (p.baseline) {
        const project::Baseline& b = *p.baseline;
        QString said = tr("on %1 by %2 (signature %3)")
                           .arg(QString::fromStdString(b.date), QString::fromStdString(b.by),
                                QString::fromStdString(compiler::signatureText(b.signature)));
        if (!b.comment.empty())
            said += QStringLiteral(": ") + QString::fromStdString(b.comment);
        m_validated->setText(said);
    } else {
        m_validated->setText(tr("not yet (Project > Mark as Validated)"));
    }
    const bool editable = m_document->permission() == project::Permission::Full;
    m_name->setReadOnly(!editable);
    m_description->setReadOnly(!editable);
    m_includeSource->setEnabled(editable);
    m_addStandard->setEnabled(editable);
    m_addUser->setEnabled(editable);
    refreshSinceValidation();
    refreshProtection();
    refreshLibraries();
    m_refreshing = false;
}

void ProjectPage::refreshProtection() {
    const project::Project& p = m_document->project();
    if (const auto& tampering = m_document->tampering()) {
        m_protection->setText(tr("changed outside Rungsmith after it was password protected "
                                 "(first at line %1): open read only")
                                  .arg(tampering->line));
        m_protection->setToolTip({});
        markAsError(m_protection);
        return;
    }
    m_protection->setPalette(QPalette()); // as the page's
    if (!p.protection) {
        m_protection->setText(tr("none (File > Password Protect)"));
        m_protection->setToolTip({});
        return;
    }
    // The key tells one protection from another: who relies on the file keeps it to compare.
    const QString key = QString::fromStdString(p.protection->key);
    QStringList groups;
    for (int i = 0; i < 16; i += 4)
        groups << key.mid(i, 4);
    const QString options =
        p.protection->options == project::OptionsAccess::Main   ? tr("only with the main password")
        : p.protection->options == project::OptionsAccess::Free ? tr("without a password")
                                                                : tr("with their own password");
    const project::Permission permission = m_document->permission();
    const QString open = permission == project::Permission::Full ? tr("with full permission")
                         : permission == project::Permission::Configure
                             ? tr("with permission to configure")
                             : tr("read only");
    m_protection->setText(tr("password protected, key %1 …\nConfig Options change %2; opened %3")
                              .arg(groups.join(QLatin1Char(' ')), options, open));
    m_protection->setToolTip(tr("The protection's public key: %1").arg(key));
}

void ProjectPage::refreshSinceValidation() {
    const project::Project& p = m_document->project();
    m_form->setRowVisible(m_sinceValidation, p.baseline.has_value());
    m_sinceValidation->setPalette(QPalette()); // as the page's, until a change is marked
    if (!p.baseline)
        return;
    const QString date = QString::fromStdString(p.baseline->date);
    const SettledCompile::Outcome* outcome = m_compile->outcome();
    if (!outcome) {
        m_sinceValidation->setText(tr("computing..."));
        return;
    }
    if (!outcome->ok || !outcome->sinceValidation) {
        m_sinceValidation->setText(
            tr("unknown while the project has errors (Build > Compile shows them)"));
        return;
    }
    const review::ProjectDiff& diff = *outcome->sinceValidation;
    std::set<int> stations(diff.changedStations.begin(), diff.changedStations.end());
    for (const review::UnitDifference& unit : diff.units)
        stations.insert(unit.station);
    for (const review::NetworkDifference& network : diff.networks)
        stations.insert(network.station);
    if (stations.empty()) {
        m_sinceValidation->setText(tr("no change in behaviour since validation on %1").arg(date));
        return;
    }
    QStringList units;
    for (const int station : stations)
        units << unitCaption(p, station);
    QString said =
        tr("changed since validation on %1 in %2").arg(date, units.join(QStringLiteral(", ")));
    if (!diff.networks.empty())
        said += QStringLiteral("; ") + tr("%n network(s) added, changed or removed", nullptr,
                                          static_cast<int>(diff.networks.size()));
    m_sinceValidation->setText(said);
    markAsError(m_sinceValidation);
}

void ProjectPage::refreshLibraries() {
    const project::Project& p = m_document->project();
    const int row = m_libraries->currentRow();
    m_libraries->clear();
    if (p.libraries.empty()) {
        // Nothing named: every library found is used, which the list says.
        auto* all = new QListWidgetItem(
            tr("Every library found: the standard ones and those in the project's folder"),
            m_libraries);
        all->setFlags(Qt::NoItemFlags);
    }
    const blocks::LibraryPlaces places{
        QCoreApplication::applicationDirPath(), m_document->path(), {}};
    const blocks::LibrarySet found = blocks::librariesFor(places, p.libraries);
    for (const auto& entry : p.libraries) {
        auto* item = new QListWidgetItem(QString::fromStdString(entry), m_libraries);
        const bool present = blocks::libraryOfEntry(found, places, entry) != nullptr;
        if (present)
            item->setToolTip(blocks::isUserLibraryEntry(entry)
                                 ? tr("A user library in the project's folder")
                                 : tr("A standard library"));
        else {
            item->setText(tr("%1 (not found)").arg(item->text()));
            item->setForeground(errorTextColor(m_libraries->palette()));
        }
    }
    if (!p.libraries.empty())
        m_libraries->setCurrentRow(std::min(std::max(row, 0), m_libraries->count() - 1));
    m_remove->setEnabled(!p.libraries.empty() && m_libraries->currentRow() >= 0 &&
                         m_document->permission() == project::Permission::Full);
}

void ProjectPage::addLibrary(const QString& entry) {
    if (!m_document)
        return;
    const std::string added = entry.toStdString();
    m_document->edit(tr("Add Library %1").arg(entry), [&](project::Project& p) {
        if (std::find(p.libraries.begin(), p.libraries.end(), added) == p.libraries.end())
            p.libraries.push_back(added);
    });
}

void ProjectPage::addUserLibrary() {
    if (!m_document)
        return;
    const QString folder = m_document->path().isEmpty()
                               ? QDir::homePath()
                               : QFileInfo(m_document->path()).absolutePath();
    const QString file = QFileDialog::getOpenFileName(this, tr("Add User Library"), folder,
                                                      tr("Function block libraries (*.rslib)"));
    if (file.isEmpty())
        return;
    // Kept relative to the project, so the two move together.
    addLibrary(m_document->path().isEmpty() ? file : QDir(folder).relativeFilePath(file));
}

void ProjectPage::removeLibrary() {
    const int row = m_libraries->currentRow();
    if (!m_document || row < 0 || row >= static_cast<int>(m_document->project().libraries.size()))
        return;
    const std::string removed = m_document->project().libraries[static_cast<std::size_t>(row)];
    m_document->edit(tr("Remove Library %1").arg(QString::fromStdString(removed)),
                     [&](project::Project& p) { p.libraries.erase(p.libraries.begin() + row); });
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
