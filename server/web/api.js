// The lab's JSON API (server/src/lib.rs lists it). Every answer that is not 2xx becomes an
// ApiError carrying the server's {file, key, reason, message}.

export class ApiError extends Error {
  constructor(status, body) {
    super(body && body.message ? body.message : `HTTP ${status}`);
    this.status = status;
    this.file = body ? body.file : "";
    this.key = body ? body.key : "";
    this.reason = body ? body.reason : "";
  }
}

async function answer(r) {
  const text = await r.text();
  let body = null;
  try {
    body = text ? JSON.parse(text) : null;
  } catch {
    body = { message: text };
  }
  if (!r.ok) throw new ApiError(r.status, body);
  return body;
}

export async function get(path) {
  return answer(await fetch(path, { headers: { accept: "application/json" } }));
}

export async function post(path, body) {
  return answer(
    await fetch(path, {
      method: "POST",
      headers: { "content-type": "application/json", accept: "application/json" },
      body: JSON.stringify(body),
    }),
  );
}

// A file answered by the server, handed to the browser as a download.
export async function download(path, body) {
  const r = await fetch(path, {
    method: "POST",
    headers: { "content-type": "application/json" },
    body: JSON.stringify(body),
  });
  if (!r.ok) await answer(r);
  const disposition = r.headers.get("content-disposition") || "";
  const m = /filename="([^"]+)"/.exec(disposition);
  const name = m ? m[1] : "download";
  const blob = await r.blob();
  const url = URL.createObjectURL(blob);
  const a = document.createElement("a");
  a.href = url;
  a.download = name;
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
  return { name, size: blob.size };
}

// Asks for job `id` to be cancelled (it ends soon after, saying so).
export async function cancelJob(id) {
  return post(`/api/jobs/${id}/cancel`, {});
}

// Polls job `id` until it ends, calling `onProgress(status)` on every poll.
export async function waitJob(id, onProgress, intervalMs = 150) {
  for (;;) {
    const s = await get(`/api/jobs/${id}`);
    onProgress(s);
    if (s.state !== "queued" && s.state !== "running") return s;
    await new Promise((r) => setTimeout(r, intervalMs));
  }
}
