#include "cli/batch.h"

#include <dirent.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>

#include "cli/json.h"
#include "cli/outputs.h"
#include "cli/progress.h"
#include "kernel/file_name.h"

namespace erd::cli {

namespace {

std::string stem(const std::string& path) {
    const std::string::size_type slash = path.rfind('/');
    std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    const std::string::size_type dot = base.rfind('.');
    if (dot != std::string::npos && dot > 0) base.resize(dot);
    return base;
}

// A record's fields through the pipe from the job's child: "<length>:<bytes>" each.
void put_field(std::string* out, const std::string& s) { *out += std::to_string(s.size()) + ":" + s; }

bool get_field(const std::string& in, std::size_t* at, std::string* s) {
    const std::size_t colon = in.find(':', *at);
    if (colon == std::string::npos) return false;
    const std::size_t n = std::size_t(std::strtoull(in.c_str() + *at, nullptr, 10));
    if (colon + 1 + n > in.size()) return false;
    *s = in.substr(colon + 1, n);
    *at = colon + 1 + n;
    return true;
}

std::string encode(const BatchRecord& r) {
    std::string out;
    put_field(&out, r.method);
    put_field(&out, std::to_string(r.points));
    put_field(&out, r.has_psnr ? (std::isinf(r.psnr) ? std::string("inf") : std::to_string(r.psnr)) : std::string());
    return out;
}

void decode(const std::string& in, BatchRecord* r) {
    std::size_t at = 0;
    std::string points, db;
    if (!get_field(in, &at, &r->method) || !get_field(in, &at, &points) || !get_field(in, &at, &db)) return;
    r->points = std::strtoll(points.c_str(), nullptr, 10);
    r->has_psnr = !db.empty();
    r->psnr = db == "inf" ? INFINITY : std::strtod(db.c_str(), nullptr);
}

std::string read_all(int fd) {
    std::string s;
    char buf[4096];
    ::lseek(fd, 0, SEEK_SET);
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        s.append(buf, std::size_t(n));
    }
    return s;
}

// One job running: its child, its captured stderr and its record pipe.
struct Running {
    std::size_t index;
    pid_t pid;
    std::FILE* messages;  // the child's stderr, an unnamed temporary file
    int record;           // read end of the record pipe
    std::chrono::steady_clock::time_point start;
};

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::string psnr_text(const BatchRecord& r) {
    if (!r.has_psnr) return "";
    if (std::isinf(r.psnr)) return "inf";
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4f", r.psnr);
    return buf;
}

std::string summary_text(const std::vector<BatchItem>& items, const std::vector<BatchRecord>& recs, bool json) {
    std::string out = json ? "[\n" : "file,method,points,psnr,seconds,status,error\n";
    for (std::size_t i = 0; i < items.size(); ++i) {
        const BatchRecord& r = recs[i];
        char secs[32];
        std::snprintf(secs, sizeof secs, "%.3f", r.seconds);
        if (json) {
            JsonObject o;
            o.str("file", items[i].input).str("method", r.method);
            if (r.points >= 0) o.integer("points", r.points); else o.null("points");
            if (r.has_psnr && !std::isinf(r.psnr)) o.num("psnr", r.psnr); else o.null("psnr");
            o.raw("seconds", secs).integer("status", r.status).str("error", r.error);
            out += "  " + o.text() + (i + 1 < items.size() ? ",\n" : "\n");
        } else {
            out += csv_field(items[i].input) + "," + csv_field(r.method) + "," + (r.points >= 0 ? std::to_string(r.points) : "") +
                   "," + psnr_text(r) + "," + secs + "," + std::to_string(r.status) + "," + csv_field(r.error) + "\n";
        }
    }
    return json ? out + "]\n" : out;
}

}  // namespace

Status expand_inputs(const std::vector<std::string>& given, const std::vector<std::string>& extensions,
                     std::vector<BatchItem>* items) {
    items->clear();
    for (const std::string& path : given) {
        struct stat st;
        if (path == "-" || ::stat(path.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
            items->push_back({path, stem(path)});  // a missing file fails in its own job
            continue;
        }
        DIR* d = ::opendir(path.c_str());
        if (!d) return Status::failure(os_error(path, errno));
        std::vector<std::string> names;
        while (const dirent* e = ::readdir(d)) {
            const std::string n = e->d_name;
            if (n.empty() || n[0] == '.') continue;
            for (const std::string& ext : extensions)
                if (has_extension(n, ext.c_str())) { names.push_back(n); break; }
        }
        ::closedir(d);
        if (names.empty()) return Status::bad_input(escape_name(path) + ": a folder without input files");
        std::sort(names.begin(), names.end());
        const std::string dir = path.back() == '/' ? path : path + "/";
        for (const std::string& n : names) items->push_back({dir + n, stem(n)});
    }
    return Status::success();
}

bool wants_batch(const std::vector<std::string>& inputs, const std::string& output, bool batch_flags) {
    struct stat st;
    return inputs.size() > 1 || has_name_field(output) || batch_flags ||
           (inputs.size() == 1 && ::stat(inputs[0].c_str(), &st) == 0 && S_ISDIR(st.st_mode));
}

bool has_name_field(const std::string& pattern) { return pattern.find("{name}") != std::string::npos; }

std::string expand_pattern(const std::string& pattern, const BatchItem& item) {
    std::string out;
    for (std::size_t i = 0; i < pattern.size();) {
        if (pattern.compare(i, 6, "{name}") == 0) {
            out += item.name;
            i += 6;
        } else {
            out += pattern[i++];
        }
    }
    return out;
}

Status check_patterns(const std::vector<BatchItem>& items, const std::vector<std::string>& patterns) {
    for (const std::string& p : patterns) {
        if (p.empty()) continue;
        if (items.size() > 1 && !has_name_field(p) && p != "/dev/null")
            return Status::bad_input(escape_name(p) + ": several inputs would write this one file; put {name} in it (out/{name}.erd)");
        std::map<std::string, std::string> seen;
        for (const BatchItem& it : items) {
            const std::string out = expand_pattern(p, it);
            auto [at, fresh] = seen.emplace(out, it.input);
            if (!fresh && items.size() > 1 && p != "/dev/null")
                return Status::bad_input(escape_name(at->second) + " and " + escape_name(it.input) + " would both write " +
                                         escape_name(out));
        }
    }
    return Status::success();
}

Status parse_jobs(const std::string& text, int* jobs) {
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || text[0] < '0' || text[0] > '9' || *end != '\0' || v < 0 || v > 256)
        return Status::bad_input("-j: '" + escape_name(text) + "' is not a number of jobs in [0, 256] (0 = one per processor)");
    const long cpus = ::sysconf(_SC_NPROCESSORS_ONLN);
    *jobs = v == 0 ? int(cpus > 0 ? cpus : 1) : int(v);
    return Status::success();
}

Status parse_parallelism(bool given, const std::string& text, bool batch, Parallelism* out) {
    const long cpus = ::sysconf(_SC_NPROCESSORS_ONLN);
    const int processors = int(cpus > 0 ? std::min(cpus, 256L) : 1L);
    int n = batch ? 1 : processors;
    if (given) {
        if (Status st = parse_jobs(text, &n); !st) return st;
    }
    out->jobs = batch ? n : 1;
    out->threads = batch ? std::max(1, processors / n) : n;
    return Status::success();
}

int run_batch(const std::vector<BatchItem>& items, int jobs, const BatchJob& job, const std::string& summary,
              const Reporter& rep, bool progress, const BatchFiles& files) {
    const auto t0 = std::chrono::steady_clock::now();
    // Each job checks its own files; across jobs only this sees that one job would overwrite the
    // input of another (a.model, a2.model -o {name}2.model) or the summary a job's output.
    std::vector<std::string> inputs, outs;
    for (const BatchItem& it : items) {
        inputs.push_back(it.input);
        for (const std::string& p : files.inputs)
            if (!p.empty() && p != "-") inputs.push_back(expand_pattern(p, it));
        for (const std::string& p : files.outputs)
            if (!p.empty() && p != "-") outs.push_back(expand_pattern(p, it));
    }
    if (!summary.empty()) outs.push_back(summary);
    if (Status st = Outputs::clashes(outs, inputs); !st) return rep.fail(st);
    // Every output's folder too, so a batch into a missing folder stops here, not after the work
    // of each file (the summary's is checked below).
    if (Status st = Outputs::folders(outs); !st) return rep.fail(st);
    Outputs outputs;
    if (!summary.empty())
        if (Status st = outputs.check({summary}, inputs); !st) return rep.fail(st);
    std::vector<BatchRecord> recs(items.size());
    std::vector<Running> running;
    Progress bar("batch", progress, progress);
    std::size_t next = 0, done = 0, failed = 0;
    std::fflush(stdout);
    std::fflush(stderr);
    while (done < items.size()) {
        while (next < items.size() && running.size() < std::size_t(std::max(1, jobs))) {
            Running r{next, -1, std::tmpfile(), -1, std::chrono::steady_clock::now()};
            int fds[2] = {-1, -1};
            if (!r.messages || ::pipe(fds) != 0) {
                if (r.messages) std::fclose(r.messages);
                return rep.fail(Status::failure(std::string("cannot start a job: ") + std::strerror(errno)));
            }
            r.record = fds[0];
            r.pid = ::fork();
            if (r.pid == 0) {
                ::close(fds[0]);
                ::dup2(fileno(r.messages), STDERR_FILENO);
                BatchRecord rec;
                const int rc = job(items[next], &rec);
                const std::string bytes = encode(rec);
                if (::write(fds[1], bytes.data(), bytes.size()) < 0) {
                }
                std::fflush(stdout);
                std::fflush(stderr);
                ::_exit(rc);
            }
            ::close(fds[1]);
            if (r.pid < 0) {
                ::close(fds[0]);
                std::fclose(r.messages);
                return rep.fail(Status::failure(std::string("cannot start a job: ") + std::strerror(errno)));
            }
            running.push_back(r);
            ++next;
        }
        int status = 0;
        const pid_t pid = ::wait(&status);
        if (pid < 0) {
            if (errno == EINTR) continue;
            break;
        }
        auto it = std::find_if(running.begin(), running.end(), [&](const Running& r) { return r.pid == pid; });
        if (it == running.end()) continue;
        BatchRecord& rec = recs[it->index];
        decode(read_all(it->record), &rec);
        ::close(it->record);
        rec.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - it->start).count();
        rec.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
        const std::string text = read_all(fileno(it->messages));
        std::fclose(it->messages);
        bar.finish();
        std::fwrite(text.data(), 1, text.size(), stderr);
        if (rec.status != 0) {
            ++failed;
            std::string last = text;
            while (!last.empty() && last.back() == '\n') last.pop_back();
            const std::string::size_type nl = last.rfind('\n');
            rec.error = nl == std::string::npos ? last : last.substr(nl + 1);
            if (rec.error.rfind("usage: ", 0) == 0 && nl != std::string::npos) {  // a usage error: its message line
                last.resize(nl);
                const std::string::size_type nl2 = last.rfind('\n');
                rec.error = nl2 == std::string::npos ? last : last.substr(nl2 + 1);
            }
            const std::string head = "erd " + rep.name() + ": ";
            if (rec.error.rfind(head, 0) == 0) rec.error.erase(0, head.size());
            if (rec.error.empty()) rec.error = WIFSIGNALED(status) ? std::string("killed by signal ") + std::to_string(WTERMSIG(status)) : "failed";
        }
        running.erase(it);
        ++done;
        bar.update("files", double(done) / double(items.size()));
    }
    bar.finish();
    if (!summary.empty()) {
        Status st = outputs.stage(summary, summary_text(items, recs, has_extension(summary, ".json")));
        if (st) st = outputs.commit();
        if (!st) return rep.fail(st);
    }
    char buf[160];
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (failed) {
        std::snprintf(buf, sizeof buf, "%zu of %zu files failed (%.2f s)", failed, items.size(), secs);
        rep.fail(Status::failure(buf));
        return 1;
    }
    std::snprintf(buf, sizeof buf, "%zu files done in %.2f s with %d jobs", items.size(), secs, std::max(1, jobs));
    rep.note(std::string(buf) + (summary.empty() ? "" : "; summary -> " + escape_name(summary)));
    return 0;
}

}  // namespace erd::cli
