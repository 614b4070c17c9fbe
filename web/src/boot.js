// Starts the page's module and, when it cannot load, says why on the page.
// A module whose import fails (three.js not installed in web/node_modules,
// a file the server does not have) leaves a blank page with its errors only
// in the console; a spectator needs words instead.
(function boot() {
  'use strict';
  const THREE_URL = './node_modules/three/build/three.module.js';

  function show(text) {
    const el = document.getElementById('status');
    el.textContent = text;
    el.classList.add('fatal');
    el.hidden = false;
  }

  async function explain() {
    let threeMissing = false;
    try {
      const r = await fetch(THREE_URL, { method: 'HEAD', cache: 'no-store' });
      threeMissing = !r.ok;
    } catch (_) {
      threeMissing = true;
    }
    show(threeMissing
      ? 'The page cannot start: three.js is missing from the server\u2019s web/node_modules. ' +
        'Run scripts/install-deps.sh (or npm ci in web/) on the server, then reload.'
      : 'The page cannot start: one of its files failed to load. Reload; if it persists, ' +
        'the browser\u2019s console names the file.');
  }

  const script = document.createElement('script');
  script.type = 'module';
  script.src = './src/main.js';
  script.onerror = explain;
  document.body.appendChild(script);
})();
