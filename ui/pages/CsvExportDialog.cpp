// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/CsvExportDialog.h"

#include "project/VariableCsv.h"

#include <QButtonGroup>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPushButton>
#include <QRadioButton>
#include <QVBoxLayout>

namespace rs::ui {

CsvExportDialog::CsvExportDialog(int station, const QString& suggestedPath, QWidget* parent)
    : QDialog(parent), m_station(station), m_scope(new QButtonGroup(this)),
      m_prefix(new QLineEdit(this)), m_order(new QButtonGroup(this)),
      m_separator(new QComboBox(this)), m_path(new QLineEdit(suggestedPath, this)) {
    setObjectName(QStringLiteral("csvExportDialog"));
    setWindowTitle(tr("Export Variable Names from Pluto %1").arg(station));

    auto radios = [this](QButtonGroup* group, const QStringList& texts) {
        auto* row = new QVBoxLayout;
        for (int i = 0; i < texts.size(); ++i) {
            auto* radio = new QRadioButton(texts[i], this);
            group->addButton(radio, i);
            row->addWidget(radio);
        }
        group->button(0)->setChecked(true);
        return row;
    };
    m_prefix->setObjectName(QStringLiteral("csvPrefixEdit"));
    m_prefix->setPlaceholderText(tr("none"));
    // Spreadsheets where the decimal separator is a comma expect ';' between fields.
    m_separator->addItem(tr("Semicolon (;)"), QStringLiteral(";"));
    m_separator->addItem(tr("Comma (,)"), QStringLiteral(","));
    m_separator->setCurrentIndex(QLocale().decimalPoint() == QStringLiteral(",") ? 0 : 1);
    m_separator->setObjectName(QStringLiteral("csvSeparatorCombo"));
    m_path->setObjectName(QStringLiteral("csvPathEdit"));
    auto* browse = new QPushButton(tr("&Browse..."), this);
    auto* file = new QHBoxLayout;
    file->addWidget(m_path, 1);
    file->addWidget(browse);

    auto* form = new QFormLayout;
    form->addRow(tr("Variables:"),
                 radios(m_scope, {tr("&Global and local"), tr("G&lobal only"), tr("L&ocal only")}));
    form->addRow(tr("&Prefix for names:"), m_prefix);
    form->addRow(tr("Sort by:"), radios(m_order, {tr("&Variable"), tr("Symbolic &name")}));
    form->addRow(tr("&Separator:"), m_separator);
    // A row's label made from text has no buddy: its '&' would show, and
    // Alt+F would lead nowhere.
    auto* fileLabel = new QLabel(tr("&File:"), this);
    fileLabel->setBuddy(m_path);
    form->addRow(fileLabel, file);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
    QPushButton* exportButton = buttons->addButton(tr("&Export"), QDialogButtonBox::AcceptRole);
    exportButton->setDefault(true);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(m_path, &QLineEdit::textChanged, exportButton,
            [exportButton](const QString& path) { exportButton->setEnabled(!path.isEmpty()); });
    connect(browse, &QPushButton::clicked, this, [this] {
        const QString chosen = QFileDialog::getSaveFileName(this, windowTitle(), m_path->text(),
                                                            tr("CSV files (*.csv);;All files (*)"));
        if (!chosen.isEmpty())
            m_path->setText(chosen);
    });
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons);
    exportButton->setEnabled(!m_path->text().isEmpty());
}

project::CsvExportOptions CsvExportDialog::options() const {
    project::CsvExportOptions options;
    options.station = m_station;
    options.scope = m_scope->checkedId() == 1   ? project::CsvScope::Global
                    : m_scope->checkedId() == 2 ? project::CsvScope::Local
                                                : project::CsvScope::All;
    options.prefix = m_prefix->text().trimmed().toStdString();
    options.order =
        m_order->checkedId() == 1 ? project::CsvOrder::ByName : project::CsvOrder::ByVariable;
    options.separator = m_separator->currentData().toString().at(0).toLatin1();
    return options;
}

QString CsvExportDialog::path() const {
    return m_path->text();
}

void CsvExportDialog::setPath(const QString& path) {
    m_path->setText(path);
}

} // namespace rs::ui
