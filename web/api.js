// The studio's JSON API (docs/studio-api.md) and its event stream, as the page uses them.

// An API error: the server's one-line message and its HTTP status.
export class ApiError extends Error {
  constructor(status, message) {
    super(message);
    this.status = status;
  }
}

async function check(response) {
  if (response.ok) return response;
  let message = `${response.status} ${response.statusText}`;
  try {
    message = (await response.json()).error || message;
  } catch (_) { /* not JSON: keep the status line */ }
  throw new ApiError(response.status, message);
}

export async function getJson(path) {
  return (await check(await fetch(path))).json();
}

export async function sendJson(method, path, body) {
  const response = await fetch(path, {
    method,
    headers: {'Content-Type': 'application/json'},
    body: body === undefined ? undefined : JSON.stringify(body),
  });
  return (await check(response)).json();
}

export async function getBytes(path) {
  return (await check(await fetch(path))).arrayBuffer();
}

// POST a file's bytes as they are; `kind` is "mesh" or "exemplar".
export async function upload(kind, file) {
  const ext = file.name.includes('.') ? file.name.split('.').pop().toLowerCase() : '';
  const query = new URLSearchParams({format: ext, name: file.name.replace(/\.[^.]*$/, '')});
  const response = await fetch(`/api/uploads/${kind}?${query}`, {method: 'POST', body: file});
  return (await check(response)).json();
}

// POST /api/export and hand the file to the browser's download.
export async function exportFile(body) {
  const response = await check(await fetch('/api/export', {
    method: 'POST', headers: {'Content-Type': 'application/json'}, body: JSON.stringify(body)}));
  const disposition = response.headers.get('Content-Disposition') || '';
  const name = (disposition.match(/filename="([^"]+)"/) || [])[1] || `texsynth-studio.${body.format}`;
  const url = URL.createObjectURL(await response.blob());
  const link = Object.assign(document.createElement('a'), {href: url, download: name});
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10000);
  return name;
}

// Calls handlers[type](data) for every event the server pushes (job, progress, result, field, scene).
export function listen(handlers) {
  const source = new EventSource('/api/events');
  for (const type of ['job', 'progress', 'result', 'field', 'scene'])
    source.addEventListener(type, (event) => handlers[type]?.(JSON.parse(event.data)));
  source.onerror = () => handlers.disconnected?.();
  source.onopen = () => handlers.connected?.();
  return source;
}
