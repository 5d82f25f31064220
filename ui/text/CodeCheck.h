// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "lang/Diagnostic.h"

#include <QFutureWatcher>
#include <QObject>

#include <memory>
#include <optional>
#include <vector>

namespace rs::lang {
struct Address;
}

namespace rs::project {
struct Project;
}

namespace rs::ui {

// The compiler's checks of a unit's code while it is typed (issue 17): what
// F7 would say of it, off the window's thread. One check runs at a time; a
// request made meanwhile waits, replacing any older one, so that the newest
// text is the one checked next. At most kMostFindings are given, errors
// first: thousands of marks would only slow typing down; F7 lists them all.
// Only the unit's code is checked (issue 23): what the other units' code
// tells its check (the variables it uses) is kept from the first check and
// found again after otherCodeChanged().
class CodeCheck : public QObject {
    Q_OBJECT
public:
    static constexpr std::size_t kMostFindings = 1000;

    explicit CodeCheck(QObject* parent = nullptr);
    // Waits for a check still running.
    ~CodeCheck() override;

    // The preference for warnings about I/O without a declaration.
    void setWarnUnconfiguredIo(bool warn) { m_warnUnconfiguredIo = warn; }
    // Checks the project for the code of the unit; the ticket comes back with the result.
    void request(const project::Project& project, const QString& projectPath, int station,
                 quint64 ticket);
    // A check runs or waits.
    bool isBusy() const;
    // The project changed other than by the checked unit's code: the next
    // request looks at the whole project again.
    void otherCodeChanged();

signals:
    // The diagnostics of the unit's code, in lines of its code.
    void checked(quint64 ticket, const rs::lang::Diagnostics& diagnostics);

private:
    struct Request;
    struct Result {
        quint64 ticket = 0;
        lang::Diagnostics diagnostics;
        int station = 0;
        quint64 generation = 0;
        bool warnUnconfiguredIo = true;
        std::shared_ptr<const std::vector<lang::Address>> usedByOtherUnits;
    };
    void startWaiting();

    QFutureWatcher<Result> m_watcher;
    std::unique_ptr<Request> m_waiting;
    bool m_warnUnconfiguredIo = true;
    // What the other units' code uses, for the check of one station's code,
    // as it was when the generation was current.
    struct OtherUnits {
        int station = 0;
        bool warnUnconfiguredIo = true;
        std::shared_ptr<const std::vector<lang::Address>> used;
    };
    std::optional<OtherUnits> m_otherUnits;
    quint64 m_generation = 0;
};

} // namespace rs::ui
