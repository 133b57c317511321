Console { Rectangle { id: r; x: 1; y: [1, (2)] } }
